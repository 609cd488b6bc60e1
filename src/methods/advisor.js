// "Model no more than the scene needs": the cheapest method whose error stays within the rounding
// an 8-bit sRGB image of the scene makes anyway, or the most accurate one when none is that good.
//
// The line is a quantisation threshold, not a visibility one. A pixel shows R·L (L: the light, at
// most display white, 1). After the sRGB transform the error is |enc(R'L) − enc(RL)| ≈
// enc'(RL)·L·|R' − R|, and enc'(x)·L grows with L on both pieces of the curve (12.92·L below
// x = 0.0031308, ∝ R^(−7/12)L^(5/12) above), so the worst light is L = 1: the error shows as
// |enc(R') − enc(R)|. Under half an 8-bit step, 0.5/255, it is no larger than the error the
// display's own rounding to 8 bits already makes (the stored code may still differ by one where
// the exact value lies near a step's edge). Whether a person can see an error of a code or a few
// depends on the content and the viewer, so the panel lets the student choose the budget.
// recommend() applies the line at every sample, at the sample's own R. As one number in linear R,
// the half step is smallest at black (0.5/255/12.92 = 1.5e-4, where the curve is steepest) and
// largest at white (4.45e-3, where it is flattest); invisibleThreshold(level) gives it at any
// level, by default at the top end, where a Fresnel term ends up near grazing and where the
// largest errors of every method here occur.
// The reason is said in the page's language: each sentence one message of the catalogue
// ("methods"), its numbers written by src/ui/format.js.
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';
import { sweepDomain } from './errorMetrics.js';
import { HALF_STEP_CODES, invisibleThreshold, srgbDecode, srgbEncode } from './displayThreshold.js';
import { methodsOfKind } from './methods.js';
import { contextFor } from './rounding.js';
import { referenceFor } from './scenes.js';
import { toDegrees } from '../optics/angles.js';
import { angle, fixed, precise, tickLabel } from '../ui/format.js';

const t = messages('methods', english);

/** @typedef {import('./scenes.js').Scene} Scene */
/**
 * A row of recommend()'s table: a method's error and cost, whether it passes the budget, and
 * whether it may be recommended at all.
 * @typedef {MethodError & { methodId: string, label: string, cost: number, costSource: 'measured' | 'static', passes: boolean,
 *   recommendable: boolean }} Row
 */
/** @typedef {import('./methods.js').Method} Method */
/**
 * A method's error over a scene: sweepDomain's statistics in linear R, the case holding the
 * largest, and the display error in 8-bit codes (largest and mean).
 * @typedef {Readonly<import('./errorMetrics.js').ErrorStats & { caseAtMax: readonly number[] | null, maxCodes: number,
 *   meanCodes: number }>} MethodError
 */

export { HALF_STEP_CODES, invisibleThreshold, srgbDecode, srgbEncode };

/**
 * |enc(value) − enc(reference)| in 8-bit codes, the value clamped as a framebuffer does; NaN → ∞.
 * @param {number} value
 * @param {number} reference
 */
export function displayCodes(value, reference) {
  if (!Number.isFinite(value)) return Infinity;
  const clamp = (/** @type {number} */ x) => Math.min(1, Math.max(0, x));
  return 255 * Math.abs(srgbEncode(clamp(value)) - srgbEncode(clamp(reference)));
}

/** @type {WeakMap<Scene, Map<string, MethodError>>} scene → Map('method|precision' → result); scenes are frozen */
const errorCache = new WeakMap();

/**
 * Error of one method over a scene's domain in a precision (the scene's by default): errorStats
 * in linear R plus maxCodes and meanCodes, the largest and the mean display error in 8-bit codes
 * (one sweep gives both), and caseAtMax. Cached per
 * scene object, method and precision (the methods are deterministic).
 * @param {Scene} scene
 * @param {Method} method
 * @param {unknown} [precision]
 * @returns {MethodError}
 */
export function methodError(scene, method, precision = scene.precision) {
  const P = contextFor(precision);
  const cache = errorCache.get(scene) ?? new Map();
  errorCache.set(scene, cache);
  const key = `${method.id}|${P.name}`;
  const known = cache.get(key);
  if (known) return known;
  const measured = measure(scene, method, P);
  cache.set(key, measured);
  return measured;
}

/**
 * @param {Scene} scene
 * @param {Method} method
 * @param {import('./rounding.js').Context} P
 */
function measure(scene, method, P) {
  return sceneErrors(scene, (cos, ...args) => method.evaluate(P, cos, ...args));
}

/**
 * The errors of `evaluate` (cos θ and a case's arguments → R) over a scene's domain against its
 * float64 reference: sweepDomain's statistics in linear R plus maxCodes and meanCodes, the display
 * error in 8-bit codes. A method's errors in an arithmetic and values read back from a GPU
 * (gpuErrors.js) are measured by this one sweep.
 * @param {Scene} scene
 * @param {(cos: number, ...args: number[]) => number} evaluate
 * @returns {MethodError}
 */
export function sceneErrors(scene, evaluate) {
  const { also, ...linear } = sweepDomain({
    evaluate,
    reference: referenceFor(scene.kind),
    cases: scene.cases,
    thetaCount: scene.thetaCount,
    weighting: scene.weighting,
    also: { codes: displayCodes },
  });
  return Object.freeze({ ...linear, maxCodes: also.codes.max, meanCodes: also.codes.mean });
}

/**
 * A row of the table in words: its method, largest |ΔR| and where, and its display error.
 * @param {Row} row
 */
function describe(row) {
  if (row.nanCount > 0) return t('rowNotFinite', { method: row.label, count: row.nanCount, shown: String(row.nanCount) });
  // The largest display error need not lie where |ΔR| is largest (sRGB is steeper for dark values): said apart.
  const args = { method: row.label, max: precise(row.max, 2), codes: fixed(row.maxCodes, 2) };
  return row.thetaAtMax === null ? t('rowErrorNoAngle', args) : t('rowError', { ...args, angle: angle(toDegrees(row.thetaAtMax), 1) });
}

/**
 * A budget in words: the display's own rounding, or a number of codes (as few decimals as it has).
 * @param {number} codes
 */
function budgetText(codes) {
  return codes === HALF_STEP_CODES ? t('budgetHalfStep') : t('budgetCodes', { count: codes, codes: tickLabel(codes, 1e-6) });
}

/**
 * Recommendation for a scene. costs: { methodId: number } in any one unit (e.g. measured ns per
 * evaluation); a method without an entry uses its static count (methods.js), so pass a cost for
 * every method of the scene's kind or none. options.budgetCodes: the largest display error
 * allowed, 0.5 (within the display's rounding) by default; options.precision overrides the scene's. options.errors:
 * { methodId: methodError-shaped stats } measured elsewhere (a GPU read-back) instead of the JS
 * emulation, with options.where naming them in the reason (the scene and precision otherwise).
 * Returns { methodId, invisible, reason, budgetCodes, precision, table } where table has one row
 * per candidate, cheapest first: { methodId, label, cost, costSource, max, mean, rms,
 * thetaAtMax (radians), maxCodes, nanCount, outOfRange, passes, recommendable } (a method kept
 * only to show a failure, such as the lecture's literal order, is charted but never recommended).
 * @param {Scene} scene
 * @param {Record<string, number> | null} [costs]
 * @param {{ budgetCodes?: number, precision?: string, errors?: Record<string, MethodError> | null, where?: string | null }} [options]
 */
export function recommend(scene, costs = {}, {
  budgetCodes = HALF_STEP_CODES, precision = scene.precision, errors = null, where: place = null,
} = {}) {
  /** @type {Row[]} */
  const table = methodsOfKind(scene.kind).map((method) => {
    const given = costs?.[method.id];
    const measured = typeof given === 'number' && Number.isFinite(given);
    const error = errors ? errors[method.id] : methodError(scene, method, precision);
    if (!error) throw new RangeError(`no error given for ${method.id}`);
    return {
      methodId: method.id,
      label: method.label,
      cost: measured ? given : method.cost.static,
      costSource: measured ? 'measured' : 'static',
      ...error,
      passes: error.nanCount === 0 && error.maxCodes < budgetCodes,
      recommendable: !method.demonstratesFailure,
    };
  });
  const byAccuracy = (/** @type {Row} */ a, /** @type {Row} */ b) => a.maxCodes - b.maxCodes || a.max - b.max;
  table.sort((a, b) => a.cost - b.cost || byAccuracy(a, b));
  const passing = table.filter((row) => row.passes && row.recommendable);
  const budget = budgetText(budgetCodes);
  const where = place ?? t('sceneIn', { scene: scene.label, precision: contextFor(precision).label });
  /** @type {Row} */
  let choice;
  let reason;
  if (passing.length > 0) {
    choice = passing[0];
    const cheaper = table.filter((row) => row.cost < choice.cost);
    const sentences = [t('reasonCheapest', { method: describe(choice), where, budget })];
    const over = cheaper.filter((row) => !row.passes);
    if (over.length > 0) sentences.push(t('reasonCheaperOver', { methods: over.map(describe).join('; ') }));
    const demos = table.filter((row) => row.passes && !row.recommendable && row.cost <= choice.cost);
    if (demos.length > 0) sentences.push(t('reasonNotRecommended', { methods: demos.map((row) => row.label).join(', ') }));
    reason = sentences.join(' ');
  } else {
    choice = [...table].sort(byAccuracy)[0];
    reason = t('reasonNone', { budget, where, method: describe(choice) });
  }
  const precisionName = errors ? precision : contextFor(precision).name;
  return { methodId: choice.methodId, invisible: passing.length > 0, reason, budgetCodes, precision: precisionName, table };
}
