// @ts-check
// Checking one answer, always by recomputing: the question's parameters from the seed, its expected
// value or true option from the optics core, then the student's answer against them. Nothing a
// handed-in file says about being right is read.
import { seededRandom } from './seededRandom.js';
import { parseAnswer } from './parseAnswer.js';
import { formatTolerance, formatValue } from './formatAnswer.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

const MAX_TYPED = 80;

/** @typedef {import('./questions.js').Question} Question */
/** @typedef {import('./questions.js').ChoiceQuestion} ChoiceQuestion */
/** @typedef {import('./questions.js').ValueQuestion} ValueQuestion */
/**
 * An answer graded: expected is the true option's id or the expected value; a value's grade also
 * has the value read, the tolerance and the unit.
 * @typedef {{ answered: boolean, correct: boolean, expected: number | string, explanation: string, value?: number,
 *   tolerance?: number, unit?: string | null }} Grade
 */

/**
 * The parameters of `question` for a seed (the same seed, the same numbers).
 * @param {Question} question
 * @param {unknown} seed
 * @returns {unknown}
 */
export function questionParams(question, seed) {
  return question.params(seededRandom(`${seed}:${question.id}`));
}

// What a question's parameters decide (its expected value, which option holds) is computed once per
// question and parameters: parameters come from short lists, so a class of hundreds repeats a few
// dozen combinations, and some cost tens of milliseconds (the asphalt question bisects over the
// panel's scene: about 45 ms a hand-in, 45 s for a class of 500 without this).
const MAX_REMEMBERED = 512; // per question; far above any question's combinations today

/**
 * A memory of one thing per question and parameters (its expected value, or its true option).
 * @template T
 * @returns {(question: object, params: unknown, compute: () => T) => T}
 */
function memory() {
  /** @type {WeakMap<object, Map<string, T>>} question → Map(parameters as JSON → value) */
  const remembered = new WeakMap();
  return (question, params, compute) => {
    let known = remembered.get(question);
    if (!known) remembered.set(question, (known = new Map()));
    const key = JSON.stringify(params);
    const found = known.get(key);
    if (found !== undefined) return found;
    const value = compute();
    if (known.size >= MAX_REMEMBERED) known.clear(); // a question with continuous parameters stays bounded
    known.set(key, value);
    return value;
  };
}
/** @type {(question: object, params: unknown, compute: () => number) => number} */
const rememberExpected = memory();
/** @type {(question: object, params: unknown, compute: () => string) => string} */
const rememberTrue = memory();

/**
 * The expected value of a numeric or predict question for these parameters (computed once).
 * @param {ValueQuestion} question
 * @param {unknown} params
 */
export const expectedValue = (question, params) => rememberExpected(question, params, () => question.expected(params));

/**
 * The option of a choice question that holds for these parameters (exactly one must).
 * @param {ChoiceQuestion} question
 * @param {unknown} params
 */
export function trueOption(question, params) {
  const options = question.options(params);
  const id = rememberTrue(question, params, () => {
    const holding = options.filter((option) => option.holds(params));
    if (holding.length !== 1) throw new Error(`${question.id}: ${holding.length} options hold for ${JSON.stringify(params)}`);
    return holding[0].id;
  });
  const option = options.find((o) => o.id === id);
  if (!option) throw new Error(`${question.id}: no option ${id}`); // options() gives the same ids every time
  return option;
}

/**
 * An answer read back from storage, an LMS or a handed-in file, as the kind of question takes it,
 * or null: a prediction is an angle from 0° to 90°, a choice one of its options, a typed answer a
 * short text. Anything else (a number for a choice, text for a prediction) is no answer.
 * @param {Question} question
 * @param {unknown} params
 * @param {unknown} raw
 * @returns {number | string | null}
 */
export function readAnswer(question, params, raw) {
  if (question.kind === 'predict') return typeof raw === 'number' && raw >= 0 && raw <= 90 ? raw : null;
  if (question.kind === 'choice') return typeof raw === 'string' && question.options(params).some((o) => o.id === raw) ? raw : null;
  return typeof raw === 'string' && raw.trim() !== '' ? raw.slice(0, MAX_TYPED) : null;
}

export { MAX_TYPED };

/**
 * Grades `answer` (typed text, a number, or an option id) to `question` with `params`. Returns
 * { answered, correct, expected, value?, tolerance?, unit?, explanation }; an answer that cannot
 * be read is answered: false with the reason as its explanation.
 * @param {Question} question
 * @param {unknown} params
 * @param {unknown} answer
 * @returns {Grade}
 */
export function gradeAnswer(question, params, answer) {
  if (question.kind === 'choice') {
    const right = trueOption(question, params);
    const chosen = question.options(params).find((option) => option.id === answer);
    if (!chosen) return { answered: false, correct: false, expected: right.id, explanation: t('grade.noOption') };
    return { answered: true, correct: chosen.id === right.id, expected: right.id, explanation: chosen.why(params) };
  }
  const expected = expectedValue(question, params);
  /** @type {import('./parseAnswer.js').ParsedAnswer} */
  const read = typeof answer !== 'number' ? parseAnswer(answer, question.unit)
    : Number.isFinite(answer) ? { ok: true, value: answer } : { ok: false, reason: t('grade.notANumber') };
  const base = { expected, tolerance: question.tolerance, unit: question.unit };
  if (!read.ok) return { ...base, answered: false, correct: false, explanation: read.reason };
  const off = Math.abs(read.value - expected);
  // A tiny allowance for the binary form of the typed decimal: 0.0415 is not exactly 0.0415.
  const correct = off <= question.tolerance * (1 + 1e-9);
  return {
    ...base,
    answered: true,
    correct,
    value: read.value,
    explanation: correct ? t('grade.withinTolerance')
      : t('grade.offBy', { off: formatValue(question, off), tolerance: formatTolerance(question) }),
  };
}
