// @ts-check
// Faults met once a panel runs: an error in its code, or its graphics context lost (a GPU reset, a
// driver update, too many tabs). Each is said in words inside the panel it belongs to, and the
// other panels go on working.
//
// Which panel a fault belongs to: a context or a frame loop made while the host runs a panel's code
// (its mount or an update) is that panel's (gl/faultOwner.js); an error
// thrown by a listener while an input event inside a panel is dispatched is that panel's
// (watchInputs); any other error is the page's (installPageFaults).
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { el } from '../ui/el.js';

const t = messages('host', english);

/** @typedef {import('../gl/faultOwner.js').FaultOwner} PanelFaults */

const messageOf = (/** @type {unknown} */ error) => (error instanceof Error ? error.message : String(error)) || t('unknownError');

/**
 * The fault line of one panel (`element`, for the host to place above the picture), shown while
 * there is something to say. restart(): the panel is mounted again (its values kept).
 * @param {{ title: string, restart: () => void }} options
 * @returns {PanelFaults & { element: HTMLElement, reset: () => void, readonly count: number, readonly lost: number }}
 */
export function createPanelFaults({ title, restart }) {
  const line = el('div', 'panel-fault');
  line.hidden = true;
  const text = el('p', 'panel-fault-text');
  text.setAttribute('role', 'status');
  const again = el('button', 'panel-fault-restart', t('restartPanel'));
  again.type = 'button';
  again.hidden = true;
  again.addEventListener('click', () => {
    error = null;
    show();
    restart();
  });
  line.append(text, again);
  let lost = 0;
  let count = 0;
  /** @type {string | null} */
  let error = null; // the last error's message

  function show() {
    const lines = [];
    if (lost) lines.push(t('contextLost'));
    if (error) lines.push(t('panelError', { title, error }));
    text.textContent = lines.join(' ');
    line.classList.toggle('panel-fault-error', Boolean(error));
    again.hidden = !error;
    line.hidden = lines.length === 0;
  }

  return {
    element: line,
    fail(reason) {
      count += 1;
      console.error(`The ${title} panel met an error:`, reason); // the details, for whoever reads the console
      const message = messageOf(reason).split('\n')[0];
      if (message === error) return;
      error = message;
      show();
    },
    contextLost() {
      lost += 1;
      show();
    },
    contextRestored() {
      lost = Math.max(0, lost - 1);
      show();
    },
    /** The panel was disposed: its contexts are gone with it. */
    reset() {
      lost = 0;
      show();
    },
    get count() { return count; },
    get lost() { return lost; },
  };
}

// Input events whose listeners are the panel's own (drags, keys, controls).
const INPUTS = ['pointerdown', 'pointermove', 'pointerup', 'click', 'dblclick', 'keydown', 'keyup', 'input', 'change', 'wheel',
  'touchstart', 'touchmove', 'focusin'];
/** @type {PanelFaults | null} */
let inputOwner = null;
let clearing = 0;

/**
 * Errors thrown while an input event inside `container` is dispatched belong to `faults`.
 * @param {HTMLElement} container
 * @param {PanelFaults} faults
 */
export function watchInputs(container, faults) {
  const mark = () => {
    inputOwner = faults;
    clearTimeout(clearing);
    // The listeners of this event run within this task; an error they throw is reported at once.
    clearing = setTimeout(() => { inputOwner = null; }, 0);
  };
  for (const type of INPUTS) container.addEventListener(type, mark, { capture: true, passive: true });
}

/**
 * The page's own handler of errors nobody caught: said in the panel they came from where that is
 * known, else once on the page (noticeHost). Still logged by the browser.
 * @param {(title: string, lines: string[]) => void} sayOnPage
 */
export function installPageFaults(sayOnPage) {
  const seen = new Set();
  const report = (/** @type {unknown} */ reason) => {
    if (inputOwner) {
      inputOwner.fail(reason);
      return;
    }
    const message = messageOf(reason).split('\n')[0];
    if (seen.has(message)) return;
    seen.add(message);
    sayOnPage(t('pageFaultTitle'), [t('pageFault', { message })]);
  };
  window.addEventListener('error', (event) => {
    if (event.error === undefined && !event.message) return; // a resource that failed to load: said where it is used
    if (/^ResizeObserver loop/.test(event.message)) return; // the browser's notice of a deferred resize, no fault
    report(event.error ?? event.message);
  });
  window.addEventListener('unhandledrejection', (event) => report(event.reason));
}
