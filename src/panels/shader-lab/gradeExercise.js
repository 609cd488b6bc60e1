// @ts-check
// Grading read-back values against the float64 core: per criterion, every case it selects must be
// finite, inside [0, 1] (to 1e-6, a float32 rounding) and, unless the criterion asks only for
// sanity, within its tolerance of the target; the result names the worst case. Pure: the values
// come from the GPU (evaluateSource in src/gl/evaluateMethodsGpu.js), the cases from gradingCases.js.
// A result holds codes and numbers; words.js says it (reasonText).
import { criterion } from './exercises.js';

/** @typedef {import('./gradingCases.js').GradingCase} GradingCase */
/** @typedef {import('./exercises.js').Criterion} Criterion */
/** @typedef {import('./exercises.js').Exercise} Exercise */
/** @typedef {'red' | 'green' | 'blue'} Channel */

/**
 * One value against its target: 'notFinite' (NaN or ±∞), 'outOfRange' (outside [0, 1]),
 * 'aboveTolerance' (farther from the target than the criterion allows) or 'fine'.
 * @typedef {'notFinite' | 'outOfRange' | 'aboveTolerance' | 'fine'} ValueKind
 */

/**
 * The value a result names: its kind, its case (with the colour channel of a conductor's, else
 * null), what the GPU gave, the target there and the difference.
 * @typedef {{ kind: ValueKind, case: GradingCase, channel: Channel | null, value: number, reference: number, error: number }} NamedValue
 */

/**
 * What a criterion found. code: 'noCase' (it selected no case), 'allSane' and 'allWithin' (it
 * passes), or the kind of the worst failure ('notFinite', 'outOfRange', 'aboveTolerance'); worst:
 * the failure to name, or the largest difference where all pass (null without a case).
 * @typedef {object} CriterionResult
 * @property {string} id
 * @property {'highp' | 'mediump'} precision
 * @property {Criterion['target']} target
 * @property {number | null} tolerance  null for a criterion that asks only for sanity
 * @property {'noCase' | 'allSane' | 'allWithin' | Exclude<ValueKind, 'fine'>} code
 * @property {boolean} pass
 * @property {number} checked  values looked at (three per case for a conductor)
 * @property {number} failed
 * @property {NamedValue | null} worst
 */

/**
 * The error against the exact R over every case with cos θ in [0, 1]: the largest and the mean
 * (NaN counts as an infinite error), and where the largest is.
 * @typedef {{ max: number, mean: number, worst: Omit<NamedValue, 'kind' | 'error'> | null }} ErrorSummary
 */

const SLACK = 1e-6;

/** @type {Channel[]} */
const CHANNEL = ['red', 'green', 'blue'];

/**
 * The values of case i: one number (dielectric) or three (conductor channels).
 * @param {ArrayLike<number>} values
 * @param {number} i
 * @param {number} width
 */
const channelsOf = (values, i, width) => Array.from({ length: width }, (_, ch) => values[i * width + ch]);
/** @returns {number[]} */
const targetsOf = (/** @type {GradingCase} */ c, /** @type {string} */ target) => {
  if (Array.isArray(c.exact)) return c.exact;
  return [target === 'schlick' && 'schlick' in c ? c.schlick : c.exact];
};
const outside = (/** @type {GradingCase} */ c) => Math.abs(c.cos - Math.min(1, Math.max(0, c.cos)));
/** @param {GradingCase} a @param {GradingCase} b */
const tieBefore = (a, b) => (outside(a) !== outside(b) ? outside(a) < outside(b) : a.cos > b.cos);
/** @type {Record<ValueKind, number>} */
const RANK = { notFinite: 3, outOfRange: 2, aboveTolerance: 1, fine: 0 };

/**
 * crit: a criterion (exercises.js); cases; values: 1 per case (dielectric) or 3 (conductor).
 * @param {Criterion} crit
 * @param {GradingCase[]} cases
 * @param {ArrayLike<number>} values
 * @returns {CriterionResult}
 */
export function gradeCriterion(crit, cases, values) {
  const width = values.length === cases.length ? 1 : 3;
  let checked = 0;
  let failed = 0;
  /** @type {NamedValue | null} */
  let worst = null; // the failure to name (NaN first, then outside [0, 1], then the largest error), or the largest error
  let worstScore = [-1, -1];
  for (const [i, c] of cases.entries()) {
    if (!crit.select(c)) continue;
    const want = targetsOf(c, crit.target);
    for (const [ch, v] of channelsOf(values, i, width).entries()) {
      checked += 1;
      const error = Math.abs(v - want[ch]);
      /** @type {ValueKind} */
      const kind = !Number.isFinite(v) ? 'notFinite' : v < -SLACK || v > 1 + SLACK ? 'outOfRange'
        : crit.target !== 'sane' && !(error <= crit.tolerance) ? 'aboveTolerance' : 'fine';
      if (kind !== 'fine') failed += 1;
      const score = [RANK[kind], Number.isFinite(error) ? error : Infinity];
      // Ties go to the most telling case: the smallest step outside [0, 1] (1.0000001 before
      // 1.001), then the one nearer head-on (89.99° before 90°).
      const better = !worst || score[0] > worstScore[0] || (score[0] === worstScore[0]
        && (score[1] > worstScore[1] || (score[1] === worstScore[1] && tieBefore(c, worst.case))));
      if (better) {
        worst = { kind, case: c, channel: width === 3 ? CHANNEL[ch] : null, value: v, reference: want[ch], error };
        worstScore = score;
      }
    }
  }
  const code = !checked ? 'noCase' : !failed ? (crit.target === 'sane' ? 'allSane' : 'allWithin') : worst.kind;
  return {
    id: crit.id, precision: crit.precision, target: crit.target, tolerance: crit.tolerance ?? null,
    code: /** @type {CriterionResult['code']} */ (code), pass: checked > 0 && failed === 0, checked, failed, worst,
  };
}

/**
 * Every criterion of an exercise: valuesFor(precision) gives the read-back for that precision.
 * @param {Exercise} exercise
 * @param {GradingCase[]} cases
 * @param {(precision: string) => ArrayLike<number>} valuesFor
 * @returns {CriterionResult[]}
 */
export function gradeExercise(exercise, cases, valuesFor) {
  return exercise.criteria.map((id) => gradeCriterion(criterion(id), cases, valuesFor(criterion(id).precision)));
}

/**
 * Error against the exact R over every case with cos θ in [0, 1] (highp).
 * @param {GradingCase[]} cases
 * @param {ArrayLike<number>} values
 * @returns {ErrorSummary}
 */
export function errorSummary(cases, values, target = 'exact') {
  const width = values.length === cases.length ? 1 : 3;
  let max = -1;
  let sum = 0;
  let count = 0;
  /** @type {ErrorSummary['worst']} */
  let worst = null;
  cases.forEach((c, i) => {
    if (c.tag === 'outside') return;
    const want = targetsOf(c, target);
    channelsOf(values, i, width).forEach((v, ch) => {
      const error = Number.isFinite(v) ? Math.abs(v - want[ch]) : Infinity;
      sum += error;
      count += 1;
      if (error > max) {
        max = error;
        worst = { case: c, channel: width === 3 ? CHANNEL[ch] : null, value: v, reference: want[ch] };
      }
    });
  });
  return { max, mean: sum / count, worst };
}
