// @ts-check
// Inside an LMS: the SCORM 1.2 run-time API (ADL, "SCORM Version 1.2 Run-Time Environment", 2001,
// §3.2), the object `API` an LMS puts on a window above the page. Found, the sheet takes the
// learner's id for its seed and their name, keeps answers in cmi.suspend_data (so they follow the
// learner to another computer), records each checked answer as an interaction (so the LMS's reports
// show every question), and at hand-in reports the recomputed score to the gradebook.
// Without an LMS, or with one whose API fails, nothing here runs and the page is the ordinary
// homework page.
import { SUSPEND_LIMIT } from '../readResume.js';

/**
 * The LMS's object, which is not the page's to trust: its functions are called by name through
 * `invoke` (RTE §3.2: LMSInitialize, LMSGetValue, LMSSetValue, LMSCommit, LMSFinish), each call
 * guarded by the caller.
 * @typedef {object} ScormApi
 */

/**
 * A property of the LMS's object, without trusting it to be one. Not own(): a run-time's functions
 * are often inherited (a class's methods), and a function may be the API.
 * @type {(object: unknown, key: string) => unknown}
 */
const member = (object, key) => ((typeof object === 'object' || typeof object === 'function') && object !== null
  // eslint-disable-next-line no-restricted-syntax -- see above: the API's methods may be inherited
  ? Reflect.get(object, key) : undefined);

/**
 * The nearest `API` on a window above (or the opener's), as the run-time's discovery does.
 * @param {Window} start
 * @returns {ScormApi | null}
 */
function findApi(start) {
  for (let win = start, hops = 0; win && hops < 12; hops += 1) {
    try {
      const api = member(win, 'API');
      if ((typeof api === 'object' || typeof api === 'function') && api !== null && typeof member(api, 'LMSInitialize') === 'function') {
        return api;
      }
    } catch {
      break; // a window of another origin: nothing above it can be reached; try the opener
    }
    if (win.parent === win) break;
    win = win.parent;
  }
  try {
    return start.opener && start.opener !== start ? findApi(start.opener) : null;
  } catch {
    return null;
  }
}

/**
 * The LMS's function `name` called with `args` on its object; throws where it is no function or
 * throws itself (the callers guard every call).
 * @param {ScormApi} api
 * @param {string} name
 * @param {unknown[]} args
 */
function invoke(api, name, args) {
  const fn = member(api, name);
  if (typeof fn !== 'function') throw new TypeError(`The LMS's API has no ${name}.`);
  return /** @type {unknown} */ (Reflect.apply(fn, api, args));
}

/**
 * cmi.core.session_time: HHHH:MM:SS.SS (RTE §3.4.2, CMITimespan).
 * @param {number} ms
 */
function timespan(ms) {
  const s = Math.max(0, ms) / 1000;
  /** @type {(n: number, w: number) => string} */
  const pad = (n, w) => String(Math.floor(n)).padStart(w, '0');
  return `${pad(s / 3600, 4)}:${pad((s % 3600) / 60, 2)}:${(s % 60).toFixed(2).padStart(5, '0')}`;
}

/**
 * { learner: { id, name }, suspendData, save(work) → bool, record(interaction) → bool,
 * report(score, total) → bool }, or null without an LMS. suspendData: what the LMS kept, unread
 * (readResume.js reads it). Every call into the LMS is guarded: an LMS that throws or refuses
 * makes a call return false, never breaks the page.
 * @param {Window} [win]
 */
export function connectScorm(win = window) {
  const api = findApi(win);
  if (!api) return null;
  /** @type {(name: string, ...args: unknown[]) => string} */
  const call = (name, ...args) => {
    try {
      return String(invoke(api, name, args));
    } catch {
      return 'false';
    }
  };
  /** @type {(key: string) => string} */
  const get = (key) => {
    try {
      return String(invoke(api, 'LMSGetValue', [key]) ?? '');
    } catch {
      return '';
    }
  };
  /** @type {(key: string, value: unknown) => boolean} */
  const set = (key, value) => call('LMSSetValue', key, String(value)) === 'true';
  const commit = () => call('LMSCommit', '') === 'true';
  let started = 0;
  let completed = false;
  const begin = () => {
    if (call('LMSInitialize', '') !== 'true') return false;
    started = Date.now();
    if (['not attempted', ''].includes(get('cmi.core.lesson_status'))) set('cmi.core.lesson_status', 'incomplete');
    commit();
    return true;
  };
  if (!begin()) return null;
  const suspendData = get('cmi.suspend_data');
  // Which elements of an interaction the LMS keeps (RTE §3.4.2.7, cmi.interactions._children). An
  // LMS that does not say ('' or an error) is tried element by element, and a refused id ends the
  // tries; one whose list has no id keeps nothing that could be told apart, and is not sent any.
  const children = get('cmi.interactions._children').split(',').map((name) => name.trim()).filter(Boolean);
  let interactions = children.length === 0 || children.includes('id');
  let open = true;
  win.addEventListener('pagehide', () => {
    if (!open) return;
    open = false;
    set('cmi.core.session_time', timespan(Date.now() - started));
    // Not yet handed in: "suspend", so the LMS resumes this attempt and keeps its suspend_data.
    set('cmi.core.exit', completed ? '' : 'suspend');
    commit();
    call('LMSFinish', '');
  });
  // Restored from the back-forward cache after LMSFinish: a new session.
  win.addEventListener('pageshow', (event) => { if (event.persisted && !open) open = begin(); });
  return {
    learner: { id: get('cmi.core.student_id'), name: get('cmi.core.student_name') },
    suspendData,
    /**
     * Keeps work in cmi.suspend_data, and commits it with the interactions recorded since.
     * @param {unknown} work
     */
    save(work) {
      const data = JSON.stringify(work);
      const kept = data.length <= SUSPEND_LIMIT && set('cmi.suspend_data', data);
      return commit() && kept;
    },
    /**
     * Appends an interaction (scormInteraction.js: its elements in writing order), committed by the
     * next save. cmi.interactions is write-only in 1.2 and the LMS journals them (RTE §3.4.2.7):
     * each check is a new one at the next index, cmi.interactions._count, never a rewrite. False
     * where the LMS keeps none; an element it does not list in _children is left out.
     * @param {Record<string, string>} interaction
     */
    record(interaction) {
      if (!open || !interactions) return false;
      const count = get('cmi.interactions._count').trim();
      if (!/^\d{1,9}$/.test(count)) return false; // no count, no index that is surely free
      const n = Number(count);
      let written = true;
      for (const [element, value] of Object.entries(interaction)) {
        if (children.length && !children.includes(element.split('.')[0])) continue;
        const ok = set(`cmi.interactions.${n}.${element}`, value);
        if (!ok && element === 'id') {
          interactions = false; // the LMS refuses interactions: no more tries, no orphaned elements
          return false;
        }
        written &&= ok;
      }
      return written;
    },
    /**
     * The score as a percentage (cmi.core.score.raw, 0–100) and the lesson completed.
     * @param {number} score
     * @param {number} total
     */
    report(score, total) {
      const ok = set('cmi.core.score.min', 0) && set('cmi.core.score.max', 100)
        && set('cmi.core.score.raw', total ? Math.round((100 * score) / total) : 0)
        && set('cmi.core.lesson_status', 'completed') && commit();
      completed ||= ok;
      return ok;
    },
  };
}
