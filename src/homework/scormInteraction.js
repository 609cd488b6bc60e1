// @ts-check
// A checked answer as a SCORM 1.2 interaction (ADL, "SCORM Version 1.2 Run-Time Environment",
// 2001, §3.4.2.7, cmi.interactions), so that an LMS's interaction report (Moodle's, and others)
// lists each question: what the learner answered, whether it was right, and the right answer.
// Each value is of the data type the RTE gives its element, in the format its type takes
// (§3.4.2.7.5 student_response, §3.4.2.7.6 correct_responses.n.pattern):
//   a typed number    → numeric: the value as read (a percentage as its fraction), a CMIDecimal;
//   typed text that is no number, or one no CMIDecimal spells → fill-in: the text, a CMIString255;
//   a prediction      → numeric: the committed angle in degrees;
//   a choice          → choice: the option's letter (a, b, c… as the options stand on the card).
// The result is the page's own judgement, as the same recomputation grades the hand-in:
// correct or wrong, and unanticipated for text the page could not read as an answer at all.
import { gradeAnswer, trueOption } from './gradeAnswer.js';
import { decimalsFor } from './formatAnswer.js';

// 1.2 spells a choice as one character, a–z or 0–9 (§3.4.2.7.5): the options' order on the card
// (question.options(params), the order the card lists them in) gives a to the first, b to the
// second, so a report's "b" is the second option the learner saw. The bank has at most three.
const LETTERS = 'abcdefghijklmnopqrstuvwxyz0123456789';

// A CMIDecimal (RTE §3.4.2, data types) has no exponent; ten digits before the point is as many
// as run-times take (scorm-again's limit), far beyond any answer to these questions.
const DECIMAL_DIGITS = 10;

/**
 * x as a CMIDecimal ("-12.5", "0.0000001"), rounded to `decimals` where given; null where none spells it.
 * @param {unknown} x
 * @param {number | null} [decimals]
 */
export function cmiDecimal(x, decimals = null) {
  if (typeof x !== 'number' || !Number.isFinite(x)) return null;
  // Unrounded, 15 significant digits: 1.1 % read as a fraction is 0.011, not 0.011000000000000001.
  let text = decimals === null ? String(Number(x.toPrecision(15))) : x.toFixed(decimals);
  if (Math.abs(Number(text)) >= 10 ** DECIMAL_DIGITS) return null;
  if (/e/i.test(text)) text = x.toFixed(20); // tiny values: String(1e-7) is "1e-7"
  if (!decimals && text.includes('.')) text = text.replace(/\.?0+$/, '');
  return Number(text) === 0 ? text.replace('-', '') : text; // -0 and "-0.00" are 0
}

/**
 * A CMIString255 (RTE §3.4.2): at most 255 characters, on one line (run-times match responses
 * with `.`, which no line end matches), no control characters, no half of a surrogate pair.
 * @param {unknown} text
 */
export function cmiString255(text) {
  // eslint-disable-next-line no-control-regex
  const clean = String(text).replace(/[\u0000-\u001f\u007f-\u009f\u2028\u2029]+/g, ' ')
    .replace(/[\ud800-\udbff](?![\udc00-\udfff])|(?<![\ud800-\udbff])[\udc00-\udfff]/g, '\ufffd');
  let cut = clean.slice(0, 255);
  if (/[\ud800-\udbff]$/.test(cut)) cut = cut.slice(0, -1); // a pair cut in two at the end
  return cut;
}

/**
 * The interaction's id, a CMIIdentifier (RTE §3.4.2: no spaces, at most 255 characters): the
 * question's place on the sheet and its id, q07-exact-r. A question asked twice on a sheet is
 * two interactions; checked again, it keeps its id, so the report groups the tries.
 * @param {number} position
 * @param {unknown} questionId
 */
export function interactionId(position, questionId) {
  return `q${String(position).padStart(2, '0')}-${String(questionId)}`.replace(/[^A-Za-z0-9_-]/g, '-').slice(0, 255);
}

/**
 * at as CMITime (RTE §3.4.2: HH:MM:SS, the learner's clock, as the LMS has no time zone for it), or null.
 * @param {unknown} at
 */
export function cmiTime(at) {
  if (!(at instanceof Date) || !Number.isFinite(at.getTime())) return null;
  return [at.getHours(), at.getMinutes(), at.getSeconds()].map((n) => String(n).padStart(2, '0')).join(':');
}

/**
 * The interaction for `answer` (as the card records it) to `question` with `params`, at place
 * `position` (1-based) on the sheet, checked at `at`: the elements under cmi.interactions.n, in
 * the order they are written (id first: the others belong to it), each a text; an element with
 * nothing to say is left out.
 * @param {{ position: number, question: import('./questions.js').Question, params: unknown, answer: unknown, at: unknown }} checked
 * @returns {Record<string, string>}
 */
export function scormInteraction({ position, question, params, answer, at }) {
  const graded = gradeAnswer(question, params, answer);
  const head = { id: interactionId(position, question.id) };
  /** @type {{ type: string, student_response: string | null, pattern: string | null }} */
  let body;
  if (question.kind === 'choice') {
    const options = question.options(params);
    const letter = (/** @type {unknown} */ optionId) => {
      const i = options.findIndex((o) => o.id === optionId);
      return i >= 0 && i < LETTERS.length ? LETTERS[i] : null;
    };
    const right = trueOption(question, params).id;
    body = letter(answer) && letter(right)
      ? { type: 'choice', student_response: letter(answer), pattern: letter(right) }
      : { type: 'fill-in', student_response: cmiString255(answer ?? ''), pattern: cmiString255(right) };
  } else {
    const pattern = cmiDecimal(graded.expected, decimalsFor(question));
    const value = graded.answered ? cmiDecimal(graded.value) : null;
    body = value !== null
      ? { type: 'numeric', student_response: value, pattern }
      : { type: 'fill-in', student_response: cmiString255(answer ?? ''), pattern };
  }
  const fields = {
    ...head,
    type: body.type,
    student_response: body.student_response,
    result: graded.answered ? (graded.correct ? 'correct' : 'wrong') : 'unanticipated',
    time: cmiTime(at),
    'correct_responses.0.pattern': body.pattern,
  };
  /** @type {Record<string, string>} */
  const written = {};
  for (const [key, value] of Object.entries(fields)) if (value !== null && value !== undefined) written[key] = value;
  return written;
}
