// @ts-check
// A student's work on one sheet, kept in this browser (localStorage) under the sheet's own key, so
// closing the page loses nothing. Where storage is refused (private mode, a sandboxed frame, a
// strict policy) the work lives for the visit only, and the page says so.
import { hashSeed } from '../seededRandom.js';
import { own } from '../../host/own.js';

const PREFIX = 'fresnel-lab:homework:';

/**
 * { work: { seed, name, answeredWith, answers, attempts }, save(), kept(), forSeed(seed) } for
 * this sheet code; `kept` false where storage is refused. forSeed(seed) drops answers made under
 * another seed (another link's ?seed=, a class seed added since): they answer other numbers.
 * @param {string} sheetCode
 * @param {number} count
 * @param {() => string} makeSeed
 */
export function openAnswerStore(sheetCode, count, makeSeed) {
  const key = `${PREFIX}${hashSeed(sheetCode).toString(36)}`;
  /** @type {Storage | null} */
  let storage = null;
  try {
    storage = window.localStorage;
    storage.getItem(key);
  } catch {
    storage = null;
  }
  /** @type {unknown} what this browser kept, which anything on the page's origin can have written */
  let saved = null;
  try {
    saved = JSON.parse(storage?.getItem(key) ?? 'null');
  } catch {
    saved = null; // damaged by hand: start again rather than fail
  }
  /** @type {(name: string) => unknown} a field of what was kept, looked up as an own key */
  const field = (name) => own(saved, name);
  /** @type {(name: string) => unknown[]} */
  const list = (name) => {
    const kept = field(name);
    return Array.from({ length: count }, (_, i) => (Array.isArray(kept) ? kept[i] ?? null : null));
  };
  const seed = field('seed');
  const name = field('name');
  const answeredWith = field('answeredWith');
  const work = {
    seed: typeof seed === 'string' && seed ? seed.slice(0, 64) : makeSeed(), // this browser's own
    name: typeof name === 'string' ? name.slice(0, 100) : '',
    /** @type {string | null} the seed the answers are for */
    answeredWith: typeof answeredWith === 'string' ? answeredWith : null,
    answers: list('answers'), // as stored: each is read for its question's kind by the sheet (readAnswer)
    attempts: list('attempts').map((n) => (typeof n === 'number' && Number.isInteger(n) && n >= 0 ? n : 0)),
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
  const forSeed = (/** @type {string} */ seed) => {
    if (work.answeredWith !== seed) {
      work.answers.fill(null);
      work.attempts.fill(0);
      work.answeredWith = seed;
    }
    save();
  };
  return { work, save, kept: () => kept, forSeed };
}
