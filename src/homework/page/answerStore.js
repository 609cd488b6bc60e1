// A student's work on one sheet, kept in this browser (localStorage) under the sheet's own key, so
// closing the page loses nothing. Where storage is refused (private mode, a sandboxed frame, a
// strict policy) the work lives for the visit only, and the page says so.
import { hashSeed } from '../seededRandom.js';

const PREFIX = 'fresnel-lab:homework:';

/** { seed, name, answers } for this sheet code, and save(); `kept` false where storage is refused. */
export function openAnswerStore(sheetCode, count, makeSeed) {
  const key = `${PREFIX}${hashSeed(sheetCode).toString(36)}`;
  let storage = null;
  try {
    storage = window.localStorage;
    storage.getItem(key);
  } catch {
    storage = null;
  }
  let saved = null;
  try {
    saved = JSON.parse(storage?.getItem(key) ?? 'null');
  } catch {
    saved = null; // damaged by hand: start again rather than fail
  }
  const answers = Array.from({ length: count }, (_, i) => {
    const a = Array.isArray(saved?.answers) ? saved.answers[i] : null;
    return typeof a === 'string' || typeof a === 'number' ? a : null;
  });
  const work = {
    seed: typeof saved?.seed === 'string' && saved.seed ? saved.seed : makeSeed(),
    name: typeof saved?.name === 'string' ? saved.name.slice(0, 100) : '',
    answers,
  };
  let kept = storage !== null;
  const save = () => {
    if (!storage) return;
    try {
      storage.setItem(key, JSON.stringify(work));
    } catch {
      kept = false; // full or refused now: the page keeps working
    }
  };
  save();
  return { work, save, kept: () => kept, clear: () => { try { storage?.removeItem(key); } catch { /* refused */ } } };
}
