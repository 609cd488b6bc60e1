// Error of a method against the float64 reference over a domain: max, weighted mean and RMS of
// |value − reference|, the angle of the max, and counts of NaN/Infinity and of values outside
// [0, 1]. θ grids are uniform in θ or weighted by the projected solid angle 2 cosθ sinθ dθ (the
// share of a convex object's pixels seen at view angle θ).

const HALF_PI = Math.PI / 2;

/** @typedef {(value: number, reference: number) => number} Metric */
/**
 * @typedef {{ count: number, max: number, mean: number, rms: number, thetaAtMax: number | null,
 *   nanCount: number, outOfRange: number }} ErrorStats
 */

/**
 * |value − reference|: the default metric.
 * @param {number} value
 * @param {number} reference
 */
export function absoluteError(value, reference) {
  return Math.abs(value - reference);
}

/**
 * cos θ with cos 90° = 0 exactly (Math.cos(π/2) is 6e-17, which would hide the grazing point).
 * @param {number} theta
 */
export function cosTheta(theta) {
  return theta === HALF_PI ? 0 : Math.cos(theta);
}

/**
 * A running accumulator: add(value, reference, theta, weight) per sample, result() at the end.
 * A non-finite value or error counts in nanCount and makes max Infinity (a NaN pixel is as wrong
 * as a pixel can be); mean and RMS are over the finite samples, weighted by weight.

 */
export function createAccumulator(metric = absoluteError) {
  let count = 0;
  let max = 0;
  /** @type {number | null} */
  let thetaAtMax = null;
  let sum = 0;
  let sumSq = 0;
  let weightSum = 0;
  let nanCount = 0;
  let outOfRange = 0;
  return {
    /**
     * @param {number} value
     * @param {number} reference
     * @param {number} theta
     */
    add(value, reference, theta, weight = 1) {
      count += 1;
      const error = metric(value, reference);
      if (!Number.isFinite(value) || !Number.isFinite(error)) {
        nanCount += 1;
        if (max !== Infinity) {
          max = Infinity;
          thetaAtMax = theta;
        }
        return error;
      }
      if (value < 0 || value > 1) outOfRange += 1;
      if (error > max || thetaAtMax === null) {
        max = error;
        thetaAtMax = theta;
      }
      sum += weight * error;
      sumSq += weight * error * error;
      weightSum += weight;
      return error;
    },
    /** @returns {ErrorStats} */
    result() {
      return {
        count,
        max,
        mean: weightSum > 0 ? sum / weightSum : NaN,
        rms: weightSum > 0 ? Math.sqrt(sumSq / weightSum) : NaN,
        thetaAtMax,
        nanCount,
        outOfRange,
      };
    },
  };
}

/**
 * Statistics of samples { value, reference, theta, weight = 1 } (theta in radians).
 * Returns { count, max, mean, rms, thetaAtMax, nanCount, outOfRange }.
 * @param {Iterable<{ value: number, reference: number, theta: number, weight?: number }>} samples
 * @param {{ metric?: Metric }} [options]
 */
export function errorStats(samples, { metric = absoluteError } = {}) {
  const acc = createAccumulator(metric);
  for (const s of samples) acc.add(s.value, s.reference, s.theta, s.weight ?? 1);
  return acc.result();
}

/**
 * count angles from 0 to π/2 inclusive (the ends matter: normal incidence and grazing), with
 * trapezoid-rule weights for the measure: 'uniform' dθ/(π/2) or 'cosine' 2 cosθ sinθ dθ.
 * Weights sum to 1. Returns { theta: Float64Array, cos: Float64Array, weight: Float64Array }.
 */
export function thetaSamples(count = 1801, weighting = 'uniform') {
  if (!Number.isInteger(count) || count < 2) throw new RangeError(`count must be an integer >= 2, got ${count}`);
  if (weighting !== 'uniform' && weighting !== 'cosine') {
    throw new RangeError(`weighting must be 'uniform' or 'cosine', got ${String(weighting)}`);
  }
  const theta = new Float64Array(count);
  const cos = new Float64Array(count);
  const weight = new Float64Array(count);
  let total = 0;
  for (let i = 0; i < count; i += 1) {
    theta[i] = i === count - 1 ? HALF_PI : (HALF_PI * i) / (count - 1);
    cos[i] = cosTheta(theta[i]);
    const density = weighting === 'cosine' ? 2 * cos[i] * Math.sin(theta[i]) : 1;
    weight[i] = (i === 0 || i === count - 1 ? 0.5 : 1) * density;
    total += weight[i];
  }
  for (let i = 0; i < count; i += 1) weight[i] /= total;
  return { theta, cos, weight };
}

/**
 * count evenly spaced values from min to max inclusive.
 * @param {number} min
 * @param {number} max
 * @param {number} count
 */
export function linspace(min, max, count) {
  if (count === 1) return [min];
  return Array.from({ length: count }, (_, i) => (i === count - 1 ? max : min + ((max - min) * i) / (count - 1)));
}

/**
 * Error over a domain: every case (an argument list after cos, e.g. [nI, nT] or [n, k, f0])
 * at every angle of thetaSamples(thetaCount, weighting), evaluate(cos, ...case) against
 * reference(cos, ...case), each evaluated once. Returns errorStats for `metric` plus caseAtMax
 * (the case holding the max) and `also`: for each extra metric in `also` ({ name: fn }), its stats.
 * @param {{ evaluate: (cos: number, ...args: number[]) => number, reference: (cos: number, ...args: number[]) => number,
 *   cases: readonly (readonly number[])[], thetaCount?: number, weighting?: string, metric?: Metric,
 *   also?: Record<string, Metric> }} domain
 * @returns {ErrorStats & { caseAtMax: readonly number[] | null, also: Record<string, ErrorStats> }}
 */
export function sweepDomain({ evaluate, reference, cases, thetaCount = 1801, weighting = 'uniform', metric, also = {} }) {
  const { theta, cos, weight } = thetaSamples(thetaCount, weighting);
  const acc = createAccumulator(metric);
  const extras = Object.entries(also).map(([name, fn]) => /** @type {const} */ ([name, createAccumulator(fn)]));
  /** @type {readonly number[] | null} */
  let caseAtMax = null;
  let best = -1;
  for (const args of cases) {
    for (let i = 0; i < theta.length; i += 1) {
      const value = evaluate(cos[i], ...args);
      const ref = reference(cos[i], ...args);
      const w = weight[i] / cases.length;
      const error = acc.add(value, ref, theta[i], w);
      for (const [, extra] of extras) extra.add(value, ref, theta[i], w);
      const e = Number.isFinite(error) ? error : Infinity;
      if (e > best) {
        best = e;
        caseAtMax = args;
      }
    }
  }
  return { ...acc.result(), caseAtMax, also: Object.fromEntries(extras.map(([name, extra]) => [name, extra.result()])) };
}
