// The SCORM 1.2 formats of an interaction's elements, as the specification writes them (ADL,
// "SCORM Version 1.2 Run-Time Environment", 2001, §3.4.2 data types and §3.4.2.7 cmi.interactions),
// stricter than run-times check them: scorm-again, for one, takes any text as a response and
// any printable text as an identifier. Shared by the unit tests and the browser test of the package.

const CMI_IDENTIFIER = /^[A-Za-z0-9_-]{1,255}$/; // no spaces, no unprintable characters
const CMI_DECIMAL = /^-?\d{1,10}(\.\d+)?$/;
const CMI_TIME = /^([01]\d|2[0-3]):[0-5]\d:[0-5]\d(\.\d{1,2})?$/;
const TYPES = ['true-false', 'choice', 'fill-in', 'matching', 'performance', 'sequencing', 'likert', 'numeric'];
const RESULTS = ['correct', 'wrong', 'unanticipated', 'neutral'];
// eslint-disable-next-line no-control-regex
const cmiString255 = (v) => typeof v === 'string' && v.length <= 255 && !/[\u0000-\u001f\u007f-\u009f\u2028\u2029]/.test(v);

/** A response or pattern in the format of its type (§3.4.2.7.5): what this page writes of each. */
const RESPONSE = {
  choice: (v) => /^[a-z0-9](,[a-z0-9])*$/.test(v),
  'fill-in': cmiString255,
  numeric: (v) => CMI_DECIMAL.test(v),
};

/**
 * What is wrong with an interaction, given as its elements under cmi.interactions.n ({ id, type,
 * student_response, result, time, 'correct_responses.0.pattern' }): a list of texts, empty when
 * each element is valid SCORM 1.2 for its type.
 */
export function interactionProblems(record) {
  const problems = [];
  const { id, type, student_response: response, result, time } = record;
  const pattern = record['correct_responses.0.pattern'];
  if (!CMI_IDENTIFIER.test(id ?? '')) problems.push(`id ${JSON.stringify(id)} is no CMIIdentifier`);
  if (!TYPES.includes(type)) problems.push(`type ${JSON.stringify(type)} is not in the vocabulary`);
  else if (!RESPONSE[type]) problems.push(`type ${type} is not one this page writes`);
  else {
    if (!RESPONSE[type](response ?? '')) problems.push(`student_response ${JSON.stringify(response)} is not a ${type} response`);
    if (pattern !== undefined && !RESPONSE[type](pattern)) problems.push(`pattern ${JSON.stringify(pattern)} is not a ${type} pattern`);
  }
  if (!(RESULTS.includes(result) || CMI_DECIMAL.test(result ?? ''))) problems.push(`result ${JSON.stringify(result)} is neither in the vocabulary nor a CMIDecimal`);
  if (time !== undefined && !CMI_TIME.test(time)) problems.push(`time ${JSON.stringify(time)} is no CMITime`);
  for (const [key, value] of Object.entries(record)) {
    if (typeof value !== 'string' || !cmiString255(value)) problems.push(`${key} is not a text of at most 255 characters on one line`);
  }
  return problems;
}
