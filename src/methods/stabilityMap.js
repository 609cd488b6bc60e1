// Stability map: a dielectric method in one precision over θ (0°–90°) × nI/nT (0.4–2.5), each
// point classified against the float64 reference (fresnelExact): NaN or infinite, outside
// [0, 1], error above a tolerance, or fine. This is where the numerical failures show:
// the slide's 1 + c² − m² at matched media near grazing, Schlick past the critical angle, and the
// exact forms in float16 near the critical angle.
import { DEG } from '../optics/angles.js';
import { fresnelExact } from '../optics/fresnel.js';
import { cosTheta, linspace } from './errorMetrics.js';
import { methodById } from './methods.js';
import { contextFor } from './rounding.js';
import { invisibleThreshold } from './advisor.js';

export const FINE = 0;
export const ABOVE_TOLERANCE = 1;
export const OUT_OF_RANGE = 2;
export const NOT_FINITE = 3;
export const CLASS_NAMES = Object.freeze(['fine', 'aboveTolerance', 'outOfRange', 'notFinite']);

export const THETA_RANGE_DEG = Object.freeze([0, 90]);
export const RATIO_RANGE = Object.freeze([0.4, 2.5]);

/** The class of one value against its reference; the worst applicable class wins. */
export function classifyValue(value, reference, tolerance) {
  if (!Number.isFinite(value)) return NOT_FINITE;
  if (value < 0 || value > 1) return OUT_OF_RANGE;
  return Math.abs(value - reference) > tolerance ? ABOVE_TOLERANCE : FINE;
}

/**
 * Ratios from 0.4 to 2.5 with the row nearest 1 set to exactly 1: matched media are the case
 * where the slide's ordering breaks (R = 1 instead of 0 at grazing), and a grid that steps
 * over 1 would hide it. With the default height 106 the step is 0.02 and 1 is on the grid anyway.
 */
function ratioRows(height) {
  const ratios = linspace(RATIO_RANGE[0], RATIO_RANGE[1], height);
  let nearest = 0;
  ratios.forEach((r, j) => {
    if (Math.abs(r - 1) < Math.abs(ratios[nearest] - 1)) nearest = j;
  });
  ratios[nearest] = 1;
  return Float64Array.from(ratios);
}

/**
 * classify(methodId, precision, { width = 181, height = 106, tolerance = invisibleThreshold() })
 * Column i is θ = 90°·i/(width − 1) (cos 90° = 0 exactly), row j is nI/nT = ratio[j] ascending,
 * evaluated as light going from nI = ratio into nT = 1. Returns { cells: Uint8Array (row-major,
 * cells[j·width + i]), counts: { fine, aboveTolerance, outOfRange, notFinite }, thetaDeg, ratio,
 * width, height, tolerance, maxError (over the finite cells), methodId, precision }.
 */
export function classify(methodId, precision, { width = 181, height = 106, tolerance = invisibleThreshold() } = {}) {
  const method = methodById(methodId);
  if (method.kind !== 'dielectric') throw new RangeError(`the stability map is for dielectric methods, got ${methodId}`);
  if (!Number.isInteger(width) || width < 2 || !Number.isInteger(height) || height < 2) {
    throw new RangeError(`width and height must be integers >= 2, got ${width} × ${height}`);
  }
  const P = contextFor(precision);
  const thetaDeg = Float64Array.from(linspace(THETA_RANGE_DEG[0], THETA_RANGE_DEG[1], width));
  const cos = thetaDeg.map((t) => cosTheta(t === 90 ? Math.PI / 2 : t * DEG));
  const ratio = ratioRows(height);
  const cells = new Uint8Array(width * height);
  const tally = [0, 0, 0, 0];
  let maxError = 0;
  for (let j = 0; j < height; j += 1) {
    for (let i = 0; i < width; i += 1) {
      const value = method.evaluate(P, cos[i], ratio[j], 1);
      const reference = fresnelExact(cos[i], ratio[j], 1);
      const cls = classifyValue(value, reference, tolerance);
      if (Number.isFinite(value)) maxError = Math.max(maxError, Math.abs(value - reference));
      cells[j * width + i] = cls;
      tally[cls] += 1;
    }
  }
  const counts = Object.fromEntries(CLASS_NAMES.map((name, k) => [name, tally[k]]));
  return { cells, counts, thetaDeg, ratio, width, height, tolerance, maxError, methodId, precision: P.name };
}
