// Grading read-back values against the float64 core: per criterion, every case it selects must be
// finite, inside [0, 1] (to 1e-6, a float32 rounding) and, unless the criterion asks only for
// sanity, within its tolerance of the target; the reason names the worst case. Pure: the values
// come from the GPU (evaluateSource in src/gl/evaluateMethodsGpu.js), the cases from gradingCases.js.
import { caseText } from './gradingCases.js';
import { criterion } from './exercises.js';
import { fixed, sci, tickLabel } from '../../ui/format.js';
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';

const t = messages('shader-lab', english);

const SLACK = 1e-6;
// A value in a reason: four decimals, a tiny one in two digits (1.2e-5), NaN and ±Infinity by name.
const num = (x) => (!Number.isFinite(x) ? String(x) : x === 0 ? '0' : Math.abs(x) >= 1e-3 ? fixed(x, 4) : sci(x, 1));

/** The values of case i: one number (dielectric) or three (conductor channels). */
const channelsOf = (values, i, width) => (width === 1 ? [values[i]] : Array.from(values.subarray(i * 3, i * 3 + 3)));
const targetsOf = (c, target) => (Array.isArray(c.exact) ? c.exact : [target === 'schlick' ? c.schlick : c.exact]);
const CHANNEL = ['red', 'green', 'blue'];
/** Where a case is, with its colour channel if it has one. */
const whereOf = (c, channel) => (channel ? t('whereChannel', { case: caseText(c), channel }) : caseText(c));
/** A tolerance as written in the criterion (0.00001, 0.001), with the page's decimal separator. */
const toleranceText = (v) => tickLabel(v, 1e-9);
const outside = (c) => Math.abs(c.cos - Math.min(1, Math.max(0, c.cos)));
const tieBefore = (a, b) => (outside(a) !== outside(b) ? outside(a) < outside(b) : a.cos > b.cos);

/**
 * crit: a criterion (exercises.js); cases; values: Float32Array, 1 per case (dielectric) or 3
 * (conductor). Returns { id, label, precision, pass, checked, failed, worst, reason }.
 */
export function gradeCriterion(crit, cases, values) {
  const width = values.length === cases.length ? 1 : 3;
  let checked = 0;
  let failed = 0;
  let worst = null; // the failure to name (NaN first, then outside [0, 1], then the largest error), or the largest error
  const rank = { notFinite: 3, outOfRange: 2, aboveTolerance: 1, fine: 0 };
  cases.forEach((c, i) => {
    if (!crit.select(c)) return;
    const got = channelsOf(values, i, width);
    const want = targetsOf(c, crit.target);
    got.forEach((v, ch) => {
      checked += 1;
      const error = Math.abs(v - want[ch]);
      const kind = !Number.isFinite(v) ? 'notFinite' : v < -SLACK || v > 1 + SLACK ? 'outOfRange'
        : crit.target !== 'sane' && !(error <= crit.tolerance) ? 'aboveTolerance' : 'fine';
      if (kind !== 'fine') failed += 1;
      const score = [rank[kind], Number.isFinite(error) ? error : Infinity];
      // Ties go to the most telling case: the smallest step outside [0, 1] (1.0000001 before
      // 1.001), then the one nearer head-on (89.99° before 90°).
      const better = !worst || score[0] > worst.score[0] || (score[0] === worst.score[0]
        && (score[1] > worst.score[1] || (score[1] === worst.score[1] && tieBefore(c, worst.case))));
      if (better) {
        worst = { score, kind, case: c, channel: width === 3 ? CHANNEL[ch] : null, value: v, reference: want[ch], error };
      }
    });
  });
  const args = {
    where: worst ? whereOf(worst.case, worst.channel) : '', target: crit.target, checked: String(checked), failed: String(failed),
    tolerance: crit.tolerance === undefined ? '' : toleranceText(crit.tolerance), value: worst ? num(worst.value) : '',
  };
  let reason;
  if (!checked) reason = t('noCase');
  else if (!failed) reason = crit.target === 'sane' ? t('allSane', args) : t('allWithin', { ...args, difference: num(worst.error) });
  else if (worst.kind === 'notFinite') reason = t('notFinite', args);
  else if (worst.kind === 'outOfRange') reason = t('outOfRange', args);
  else reason = t('aboveTolerance', { ...args, reference: num(worst.reference), error: num(worst.error) });
  return { id: crit.id, label: crit.label, precision: crit.precision, pass: checked > 0 && failed === 0, checked, failed, worst, reason };
}

/** Every criterion of an exercise: valuesFor(precision) gives the read-back for that precision. */
export function gradeExercise(exercise, cases, valuesFor) {
  return exercise.criteria.map((id) => gradeCriterion(criterion(id), cases, valuesFor(criterion(id).precision)));
}

/**
 * Error against the exact R over every case with cos θ in [0, 1] (highp): { max, mean, worst }
 * (NaN counts as an infinite error, so the mean says so too).
 */
export function errorSummary(cases, values, target = 'exact') {
  const width = values.length === cases.length ? 1 : 3;
  let max = -1;
  let sum = 0;
  let count = 0;
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
  return { max, mean: sum / count, worst, where: worst ? whereOf(worst.case, worst.channel) : '' };
}
