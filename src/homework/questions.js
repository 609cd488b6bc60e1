// @ts-check
// The homework questions, each on a panel of the lecture. Every expected answer is computed by the
// float64 optics core (src/optics), never typed in: a numeric question gives its value and its
// tolerance; a choice question gives options whose truth the core decides (each wrong option comes
// with the explanation the panel shows). Parameters come from a seeded generator, so two students
// get different numbers and a seed gives the same ones back (seededRandom.js).
//   kind 'numeric': typed, with units, checked at the tolerance stated in the prompt;
//   kind 'predict': an angle committed before the panel shows the truth; `curve` is what the
//                   prediction is drawn against once the truth is shown (it stays drawn);
//                   `axis()`, where given, names what the 0°–90° axis measures (else θ from the normal),
//                   and `axisInText()` names it as a sentence does;
//   kind 'choice':  one option holds.
// Every question has `state(p)`: the values its panel starts from, and `graded`: the physical
// quantity it grades and why a student can reason to it from what the panel shows. A quantity that
// depends on a camera, a frame or a display choice says so in the prompt. tests/unit/homeworkGraded.test.js
// computes each graded quantity again without the lab's code.
import { LIGHT_QUESTIONS } from './lightQuestions.js';
import { FRESNEL_QUESTIONS } from './fresnelQuestions.js';
import english from 'virtual:messages/en/questions';
import { messages } from '../i18n/messages.js';

const t = messages('questions', english);

/** @typedef {import('./questionParts.js').Question} Question */
/** @typedef {import('./questionParts.js').ChoiceQuestion<unknown>} ChoiceQuestion */
/**
 * A question whose answer is a value (typed or predicted), checked at its tolerance.
 * @typedef {import('./questionParts.js').NumericQuestion<unknown> | import('./questionParts.js').PredictQuestion<unknown>} ValueQuestion
 */

export const QUESTIONS = Object.freeze([...LIGHT_QUESTIONS, ...FRESNEL_QUESTIONS].map((q) => Object.freeze(q)));

const byId = new Map(QUESTIONS.map((q) => [q.id, q]));

/** What a kind of question is called on the page, in the page's language. */
export const kindName = (/** @type {string} */ kind) => t(`kind.${kind}`);

/**
 * What each kind is called on the page: each name is read when it is written (a getter), so it is
 * in the language the page chose after this module loaded.
 */
export const KIND_NAMES = Object.freeze({
  get numeric() { return kindName('numeric'); },
  get predict() { return kindName('predict'); },
  get choice() { return kindName('choice'); },
});

/**
 * The question with this id, or undefined.
 * @param {unknown} id
 * @returns {Readonly<Question> | undefined}
 */
export const questionById = (id) => (typeof id === 'string' ? byId.get(id) : undefined);

/**
 * The question a checked sheet or lecture names (readSheet and readLecture keep no other id);
 * throws on an id the bank does not have.
 * @param {string} id
 * @returns {Readonly<Question>}
 */
export function knownQuestion(id) {
  const question = byId.get(id);
  if (!question) throw new RangeError(`No question ${id} in the bank.`);
  return question;
}
