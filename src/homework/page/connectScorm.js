// Inside an LMS: the SCORM 1.2 run-time API (ADL, "SCORM Version 1.2 Run-Time Environment", 2001,
// §3.2), the object `API` an LMS puts on a window above the page. Found, the sheet takes the
// learner's id as its seed and their name, keeps answers in cmi.suspend_data (so they follow the
// learner to another computer), and at hand-in reports the recomputed score to the gradebook.
// Without an LMS nothing here runs and the page is the ordinary homework page.

const SUSPEND_LIMIT = 4096; // cmi.suspend_data holds at most 4096 characters in SCORM 1.2

/** The nearest `API` on a parent window (or the opener's), as the run-time's discovery does. */
function findApi(start) {
  for (let win = start, hops = 0; win && hops < 12; hops += 1) {
    try {
      if (win.API && typeof win.API.LMSInitialize === 'function') return win.API;
    } catch {
      return null; // a parent of another origin: no API can be reached through it
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

/** { learner: { id, name }, resume, save(work), report(score, total) }, or null without an LMS. */
export function connectScorm(win = window) {
  const api = findApi(win);
  if (!api || String(api.LMSInitialize('')) !== 'true') return null;
  const get = (key) => String(api.LMSGetValue(key) ?? '');
  const set = (key, value) => api.LMSSetValue(key, String(value));
  let resume;
  try {
    resume = JSON.parse(get('cmi.suspend_data') || 'null');
  } catch {
    resume = null;
  }
  if (['not attempted', ''].includes(get('cmi.core.lesson_status'))) set('cmi.core.lesson_status', 'incomplete');
  api.LMSCommit('');
  let finished = false;
  win.addEventListener('pagehide', () => {
    if (finished) return;
    finished = true;
    api.LMSCommit('');
    api.LMSFinish('');
  });
  return {
    learner: { id: get('cmi.core.student_id'), name: get('cmi.core.student_name') },
    resume,
    save(work) {
      const data = JSON.stringify(work);
      if (data.length <= SUSPEND_LIMIT) set('cmi.suspend_data', data);
      api.LMSCommit('');
    },
    /** The score as a percentage (cmi.core.score.raw, 0–100) and the lesson completed. */
    report(score, total) {
      set('cmi.core.score.min', 0);
      set('cmi.core.score.max', 100);
      set('cmi.core.score.raw', total ? Math.round((100 * score) / total) : 0);
      set('cmi.core.lesson_status', 'completed');
      api.LMSCommit('');
    },
  };
}
