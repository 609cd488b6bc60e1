// The stability map's grid for values computed elsewhere (on the GPU): the inputs of every cell
// in the layout of stabilityMap.classify(), and the classification of values read back against
// the same float64 reference with the same classifyValue, so a GPU map and a JS map of one
// method differ only where the arithmetic differs.
import { criticalAngle, fresnelExact } from '../optics/fresnel.js';
import { cosTheta } from './errorMetrics.js';
import { classifyValue, CLASS_NAMES } from './stabilityMap.js';
import { DEG } from '../optics/angles.js';

/**
 * A classified map (classify()'s shape): each cell's class (an index of CLASS_NAMES, row-major),
 * the count of each class, the grid's θ columns and n_i/n_t rows, the tolerance, the largest
 * error over the finite cells, and what the map is of.
 * @typedef {{ cells: Uint8Array, counts: Record<'fine' | 'aboveTolerance' | 'outOfRange' | 'notFinite', number>,
 *   thetaDeg: Float64Array, ratio: Float64Array, width: number, height: number, tolerance: number, maxError: number,
 *   methodId: string, precision: string }} GridMap
 */

/** cos θ of a column, exactly as classify() computes it (cos 90° = 0). */
export function columnCos(thetaDeg) {
  return cosTheta(thetaDeg === 90 ? Math.PI / 2 : thetaDeg * DEG);
}

/**
 * GPU inputs for a map's grid ({ thetaDeg, ratio, width, height } from classify()): a Float32Array
 * of (cos θ, nI = ratio, nT = 1, 0) per cell, row-major (cell j·width + i), as classify evaluates.
 */
export function gridInputs({ thetaDeg, ratio, width, height }) {
  const inputs = new Float32Array(width * height * 4);
  for (let j = 0; j < height; j += 1) {
    for (let i = 0; i < width; i += 1) inputs.set([columnCos(thetaDeg[i]), ratio[j], 1, 0], (j * width + i) * 4);
  }
  return inputs;
}

/**
 * Classifies values (one per cell, row-major) on a map's grid against fresnelExact in float64.
 * grid: { thetaDeg, ratio, width, height, tolerance }. Returns classify()'s shape: { cells, counts,
 * thetaDeg, ratio, width, height, tolerance, maxError, ...labels } (labels: e.g. methodId, precision).
 * @returns {GridMap}
 */
export function classifyGrid(values, grid, labels = {}) {
  const { thetaDeg, ratio, width, height, tolerance } = grid;
  if (values.length !== width * height) throw new RangeError(`expected ${width * height} values, got ${values.length}`);
  const cells = new Uint8Array(width * height);
  const tally = [0, 0, 0, 0];
  let maxError = 0;
  for (let j = 0; j < height; j += 1) {
    for (let i = 0; i < width; i += 1) {
      const value = values[j * width + i];
      const reference = fresnelExact(columnCos(thetaDeg[i]), ratio[j], 1);
      const cls = classifyValue(value, reference, tolerance);
      if (Number.isFinite(value)) maxError = Math.max(maxError, Math.abs(value - reference));
      cells[j * width + i] = cls;
      tally[cls] += 1;
    }
  }
  const counts = Object.fromEntries(CLASS_NAMES.map((name, k) => [name, tally[k]]));
  return { cells, counts, thetaDeg, ratio, width, height, tolerance, maxError, ...labels };
}

/** One cell's coordinates and float64 reference: { i, j, thetaDeg, ratio, cos, reference }. */
export function cellAt(grid, i, j) {
  const thetaDeg = grid.thetaDeg[i];
  const cos = columnCos(thetaDeg);
  return { i, j, thetaDeg, ratio: grid.ratio[j], cos, reference: fresnelExact(cos, grid.ratio[j], 1) };
}

/** Critical angle in degrees for light from nI/nT = ratio into 1, or null when ratio ≤ 1. */
export function criticalAngleDeg(ratio) {
  const rad = criticalAngle(ratio, 1);
  return rad === null ? null : rad / DEG;
}
