// The audio trace under an R(θ) plot: a θ cursor moved with the keys, whose value is heard as a
// pitch (audioTraceMath.js, traceSound.js) and read out in a live region, with its own sounds for
// the Brewster angle, the critical angle and the total-internal-reflection range. Off by default;
// one switch for the page (the A key, the button under any plot, ?audio=1, or a message), so a
// student who turned it on hears every plot.
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';
import { el, button } from './el.js';
import { angle, fixed } from './format.js';
import { cuesBetween, inTir, pitchHz, stepCursor, sweepPlan, traceReadout } from './audioTraceMath.js';
import { createTraceSound } from './traceSound.js';

const t = messages('ui', english);
let on = false;
const switches = new Set();
const traces = new Set(); // { root, cursor } of each trace on the page
/** @type {ReturnType<typeof createTraceSound> | null} */
let sound = null;
const sharedSound = () => (sound ??= createTraceSound());

/** Whether the trace is on (page-wide). */
export const audioTraceOn = () => on;

/**
 * Turns the trace on or off for the page; listeners hear (on, source).
 * @param {unknown} next  on when truthy
 * @param {string} [source]  who switched it: 'page' (a key, a button), 'url', 'api' (a message)
 */
export function setAudioTrace(next, source = 'page') {
  if (Boolean(next) === on) return;
  on = Boolean(next);
  if (!on) sound?.stop();
  for (const listener of switches) listener(on, source);
}

/**
 * listener(on, source) on every switch; returns a function that removes it.
 * @param {(on: boolean, source: string) => void} listener
 */
export function onAudioTrace(listener) {
  switches.add(listener);
  return () => switches.delete(listener);
}

/** The page's sounds so far (for tests: a headless browser has no speakers). */
export const traceLog = () => sharedSound().log;

/**
 * The A key turns the trace on and off anywhere but in a text field; turned on, the cursor of
 * the plot in the focused panel (else the first plot on screen) takes the focus.
 */
export function installAudioKey(target = document) {
  target.addEventListener('keydown', (event) => {
    if (event.key !== 'a' && event.key !== 'A') return;
    if (event.ctrlKey || event.metaKey || event.altKey || event.defaultPrevented) return;
    const from = event.target instanceof Element ? event.target : null;
    if (from?.closest('input, select, textarea, [contenteditable], .cm-editor')) return;
    event.preventDefault();
    setAudioTrace(!on, 'key');
    if (!on) return;
    const list = [...traces];
    const inPanel = from && list.find((t) => t.root.closest('section, #embed')?.contains(from));
    const onScreen = list.find((t) => {
      const box = t.root.getBoundingClientRect();
      return box.bottom > 0 && box.top < window.innerHeight;
    });
    (inPanel ?? onScreen ?? list[0])?.cursor.focus();
  });
}

let ids = 0;

/**
 * A trace under `plotHost` (inserted after it). plot: createLinePlot's handle (the cursor is
 * drawn on it); curves(): [{ label, at(deg) }] with the panel's values now, each computed
 * exactly; landmarks(): { brewster, critical } in degrees (null where there is none).
 * @param {HTMLElement} plotHost
 * @param {{ plot: { setCursor: (deg: number | null, label?: string) => void },
 *   curves: () => { label: string, at: (deg: number) => number }[],
 *   landmarks: () => import('./audioTraceMath.js').Landmarks }} options
 */
export function createAudioTrace(plotHost, { plot, curves, landmarks }) {
  const id = `trace-${++ids}`;
  const root = el('div', 'trace');
  const toggle = button(t('traceToggle'), 'trace-toggle');
  toggle.setAttribute('aria-keyshortcuts', 'A');
  const keyHint = el('span', 'trace-key', t('traceKey'));
  const body = el('div', 'trace-body');
  const curveLabel = el('label', 'trace-field');
  const curveSelect = el('select');
  curveLabel.append(el('span', null, t('traceCurve')), curveSelect);
  const cursorLabel = el('span', 'trace-cursor-label', t('traceCursor'));
  cursorLabel.id = `${id}-label`;
  const cursor = el('div', 'trace-cursor');
  cursor.tabIndex = 0;
  cursor.setAttribute('role', 'slider');
  cursor.setAttribute('aria-labelledby', cursorLabel.id);
  cursor.setAttribute('aria-valuemin', '0');
  cursor.setAttribute('aria-valuemax', '90');
  cursor.setAttribute('aria-orientation', 'horizontal');
  const sweepButton = button(t('tracePlay'), 'trace-sweep');
  const readout = el('p', 'trace-readout');
  readout.setAttribute('role', 'status');
  readout.setAttribute('aria-live', 'polite');
  const help = el('p', 'trace-help', t('traceHelp'));
  body.append(curveLabel, cursorLabel, cursor, sweepButton, readout, help);
  root.append(toggle, keyHint, body);
  plotHost.after(root);

  let deg = 0;
  const traced = () => {
    const list = curves();
    return list[Math.min(list.length - 1, curveSelect.selectedIndex < 0 ? 0 : curveSelect.selectedIndex)];
  };

  function fillCurves() {
    const labels = curves().map((c) => c.label);
    const current = [...curveSelect.options].map((o) => o.textContent);
    if (labels.join('|') !== current.join('|')) curveSelect.replaceChildren(...labels.map((label) => el('option', null, label)));
    curveLabel.hidden = labels.length < 2;
  }

  /** The cursor's state on screen and in words; `cues`: landmarks just passed. */
  function show(cues = []) {
    const curve = traced();
    const value = curve.at(deg);
    cursor.setAttribute('aria-valuenow', String(deg));
    cursor.setAttribute('aria-valuetext', angle(deg, 1));
    cursor.textContent = angle(deg, 1);
    readout.textContent = traceReadout(deg, [{ label: curve.label, value }], { ...landmarks(), cues });
    plot.setCursor(on ? deg : null, t('traceMark', { angle: angle(deg, 1) }));
    return value;
  }

  function move(to) {
    const marks = landmarks();
    const cues = cuesBetween(deg, to, marks);
    deg = to;
    const value = show(cues);
    sharedSound().tone(pitchHz(value), { tir: inTir(deg, marks.critical), cues });
  }

  function sweep() {
    const plan = sweepPlan(traced().at, landmarks());
    sharedSound().sweep(plan);
    const cues = plan.cues.map((c) => t(c.kind === 'brewster' ? 'traceCueBrewster' : 'traceCueCritical', { angle: angle(c.deg) }));
    const words = { curve: traced().label, seconds: fixed(plan.seconds, 0), cues: cues.join(', ') };
    readout.textContent = t(cues.length ? 'tracePlayingCues' : 'tracePlaying', words);
  }

  function apply() {
    body.hidden = !on;
    toggle.setAttribute('aria-pressed', String(on));
    fillCurves();
    show();
  }

  const onKey = (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    if (event.key === ' ' || event.key === 'Enter') {
      event.preventDefault();
      sweep();
      return;
    }
    const to = stepCursor(deg, event.key, event.shiftKey);
    if (to === null) return;
    event.preventDefault(); // the page's and the deck's keys stay where they were
    move(to);
  };
  cursor.addEventListener('keydown', onKey);
  toggle.addEventListener('click', () => setAudioTrace(!on, 'button'));
  sweepButton.addEventListener('click', sweep);
  curveSelect.addEventListener('change', () => move(deg));
  const entry = { root, cursor };
  traces.add(entry);
  const stop = onAudioTrace(apply);
  apply();

  return {
    element: root,
    get deg() { return deg; },
    get readout() { return readout.textContent; },
    /** Moves the cursor to `to` degrees as the keys do (sound and words). */
    moveTo: (to) => move(Math.min(90, Math.max(0, Math.round(to * 10) / 10))),
    /** The values changed (indices, a metal): the words and the cursor follow, silently. */
    refresh() {
      fillCurves();
      show();
    },
    dispose() {
      stop();
      traces.delete(entry);
      cursor.removeEventListener('keydown', onKey);
      root.remove();
    },
  };
}
