// @ts-check
// A made-up class for tests and the benchmark (bench/classBench.js): a sheet of `questions` items,
// `students` hand-ins with right, wrong and missing answers drawn from a seed, as an LMS would give
// them (a folder per student in one zip), as separate files, and as text of codes one per line.
// Wrong numbers are the true value times a factor a slip gives (×2, ×½, radians for degrees, a
// percentage for a fraction) or a little off, so the class summary has peaks to find.
import { strToU8, zipSync } from 'fflate';
import { QUESTIONS, knownQuestion } from '../questions.js';
import { expectedValue, questionParams, trueOption } from '../gradeAnswer.js';
import { formatValue } from '../formatAnswer.js';
import { seededRandom } from '../seededRandom.js';
import { handInToCode, makeHandIn } from '../sheetCodes.js';
import { SHEET_VERSION } from '../readSheet.js';

const FIRST = [
  'Ada', 'Zoë', 'Łukasz', 'José', 'Aoife', 'Chloé', 'Mia', 'Noah', 'Søren', 'Yūki', 'Amara', 'Björn', 'Ingrid', 'Ravi', 'Lena', 'Tomás',
];
const LAST = [
  'Lovelace', 'Müller', 'Nowak', 'García', 'O’Brien', 'Dubois', 'Rossi', 'Kim', 'Jensen', 'Tanaka', 'Okafor', 'Berg', 'Larsen', 'Patel',
  'Novák', 'Silva',
];
const WRONG_FACTORS = [2, 0.5, Math.PI / 180, 100, 1.3, 0.8];
const START = Date.UTC(2026, 0, 15, 9);

/** @type {(x: number, step: number) => number} */
const round = (x, step) => Math.round(x / step) * step;
const clamp = (/** @type {number} */ x) => Math.min(90, Math.max(0, x));

/**
 * The answer a student gives: 'right', 'wrong' or 'none', as each kind of question takes it.
 * @param {import('../questions.js').Question} question
 * @param {unknown} params
 * @param {'right' | 'wrong' | 'none'} how
 * @param {ReturnType<typeof seededRandom>} rng
 */
function answerFor(question, params, how, rng) {
  if (how === 'none') return null;
  if (question.kind === 'choice') {
    const right = trueOption(question, params).id;
    if (how === 'right') return right;
    const others = question.options(params).filter((o) => o.id !== right);
    return others.length ? rng.pick(others).id : right;
  }
  const expected = expectedValue(question, params);
  if (question.kind === 'predict') {
    const off = how === 'right'
      ? (rng.next() - 0.5) * question.tolerance
      : (rng.next() < 0.5 ? -1 : 1) * (question.tolerance + 1 + 30 * rng.next());
    return round(clamp(expected + off), 0.1);
  }
  return formatValue(question, how === 'right' ? expected : expected * rng.pick(WRONG_FACTORS));
}

/**
 * @param {{ students?: number, questions?: number, seed?: string, classSeed?: string, right?: number, unanswered?: number }} [options]
 *   right: the share of answers right; unanswered: the share left out; classSeed: one seed for all.
 * @returns {{ sheet: import('../readSheet.js').Sheet, handIns: { source: string, data: ReturnType<typeof makeHandIn> }[],
 *   files: { name: string, bytes: Uint8Array }[], zip: Uint8Array, codes: string }}
 */
export function syntheticClass({ students = 500, questions = 40, seed = 'synthetic', classSeed, right = 0.6, unanswered = 0.05 } = {}) {
  const rng = seededRandom(`class:${seed}`);
  const order = [...QUESTIONS];
  for (let i = order.length - 1; i > 0; i -= 1) { // Fisher–Yates
    const j = Math.floor(rng.next() * (i + 1));
    [order[i], order[j]] = [order[j], order[i]];
  }
  const items = Array.from({ length: questions }, (_, i) => ({ question: order[i % order.length].id }));
  /** @type {import('../readSheet.js').Sheet} */
  const sheet = {
    version: SHEET_VERSION, title: `Synthetic class (${seed})`, reveal: 'after-answer', ...(classSeed ? { seed: classSeed } : {}), items,
  };
  /** @type {{ source: string, data: ReturnType<typeof makeHandIn> }[]} */
  const handIns = [];
  /** @type {{ name: string, bytes: Uint8Array }[]} */
  const files = [];
  /** @type {import('fflate').Zippable} */
  const tree = {};
  for (let k = 0; k < students; k += 1) {
    const pairs = FIRST.length * LAST.length;
    const name = `${FIRST[k % FIRST.length]} ${LAST[Math.floor(k / FIRST.length) % LAST.length]}`
      + `${k >= pairs ? ` ${Math.floor(k / pairs) + 1}` : ''}`;
    const studentSeed = classSeed ?? `${seed}-${k}-${Math.floor(rng.next() * 1e9).toString(36)}`;
    const answers = items.map((item) => {
      const question = knownQuestion(item.question);
      const roll = rng.next();
      const how = roll < unanswered ? 'none' : roll < unanswered + right * (1 - unanswered) ? 'right' : 'wrong';
      return answerFor(question, questionParams(question, studentSeed), how, rng);
    });
    const attempts = answers.map((a) => (a === null ? 0 : 1 + Math.floor(rng.next() * 3)));
    const data = makeHandIn({ sheet, seed: studentSeed, name, answers, attempts, time: new Date(START + k * 60_000).toISOString() });
    const folder = `${name}_${100000 + k}_assignsubmission_file_`;
    const bytes = strToU8(JSON.stringify(data));
    handIns.push({ source: `${folder}/handin.json`, data });
    files.push({ name: `${folder}/handin.json`, bytes });
    tree[folder] = { 'handin.json': bytes };
  }
  return { sheet, handIns, files, zip: zipSync(tree), codes: handIns.map((h) => handInToCode(h.data)).join('\n') };
}
