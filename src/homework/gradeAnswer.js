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

/** The parameters of `question` for a seed (the same seed, the same numbers). */
export function questionParams(question, seed) {
  return question.params(seededRandom(`${seed}:${question.id}`));
}

// What a question's parameters decide (its expected value, which option holds) is computed once per
// question and parameters: parameters come from short lists, so a class of hundreds repeats a few
// dozen combinations, and some cost tens of milliseconds (the asphalt question bisects over the
// panel's scene: about 45 ms a hand-in, 45 s for a class of 500 without this).
const MAX_REMEMBERED = 512; // per question; far above any question's combinations today
const remembered = new WeakMap(); // question → Map(kind + parameters as JSON → value)

function remember(question, kind, params, compute) {
  let known = remembered.get(question);
  if (!known) remembered.set(question, (known = new Map()));
  const key = `${kind}:${JSON.stringify(params)}`;
  if (known.has(key)) return known.get(key);
  const value = compute();
  if (known.size >= MAX_REMEMBERED) known.clear(); // a question with continuous parameters stays bounded
  known.set(key, value);
  return value;
}

/** The expected value of a numeric or predict question for these parameters (computed once). */
export const expectedValue = (question, params) => remember(question, 'expected', params, () => question.expected(params));

/** The option of a choice question that holds for these parameters (exactly one must). */
export function trueOption(question, params) {
  const options = question.options(params);
  const id = remember(question, 'true', params, () => {
    const holding = options.filter((option) => option.holds(params));
    if (holding.length !== 1) throw new Error(`${question.id}: ${holding.length} options hold for ${JSON.stringify(params)}`);
    return holding[0].id;
  });
  return options.find((option) => option.id === id);
}

/**
 * An answer read back from storage, an LMS or a handed-in file, as the kind of question takes it,
 * or null: a prediction is an angle from 0° to 90°, a choice one of its options, a typed answer a
 * short text. Anything else (a number for a choice, text for a prediction) is no answer.
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
 */
export function gradeAnswer(question, params, answer) {
  if (question.kind === 'choice') {
    const right = trueOption(question, params);
    const chosen = question.options(params).find((option) => option.id === answer);
    if (!chosen) return { answered: false, correct: false, expected: right.id, explanation: t('grade.noOption') };
    return { answered: true, correct: chosen.id === right.id, expected: right.id, explanation: chosen.why(params) };
  }
  const expected = expectedValue(question, params);
  const read = typeof answer === 'number' ? { ok: Number.isFinite(answer), value: answer, reason: t('grade.notANumber') }
    : parseAnswer(answer, question.unit);
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
