// A student's work on one sheet, kept in this browser (localStorage) under the sheet's own key, so
// closing the page loses nothing. Where storage is refused (private mode, a sandboxed frame, a
// strict policy) the work lives for the visit only, and the page says so.
import { hashSeed } from '../seededRandom.js';

const PREFIX = 'fresnel-lab:homework:';

/**
 * { work: { seed, name, answeredWith, answers, attempts }, save(), kept(), forSeed(seed) } for
 * this sheet code; `kept` false where storage is refused. forSeed(seed) drops answers made under
 * another seed (another link's ?seed=, a class seed added since): they answer other numbers.
 */
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
  const list = (name) => Array.from({ length: count }, (_, i) => (Array.isArray(saved?.[name]) ? saved[name][i] ?? null : null));
  const work = {
    seed: typeof saved?.seed === 'string' && saved.seed ? saved.seed.slice(0, 64) : makeSeed(), // this browser's own
    name: typeof saved?.name === 'string' ? saved.name.slice(0, 100) : '',
    answeredWith: typeof saved?.answeredWith === 'string' ? saved.answeredWith : null, // the seed the answers are for
    answers: list('answers'), // as stored: each is read for its question's kind by the sheet (readAnswer)
    attempts: list('attempts').map((n) => (Number.isInteger(n) && n >= 0 ? n : 0)),
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
  const forSeed = (seed) => {
    if (work.answeredWith !== seed) {
      work.answers.fill(null);
      work.attempts.fill(0);
      work.answeredWith = seed;
    }
    save();
  };
  return { work, save, kept: () => kept, forSeed };
}
