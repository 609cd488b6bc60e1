// Ground truth for a mip texel: the moments of the exact analytic normals over its footprint, by
// supersampling on an n × n midpoint grid (the supersampled reference of MJP's SpecularAA sample,
// TheRealMJP/SpecularAA, taken here in texture space). The quantities are the pyramid's
// (PYRAMID_LAYOUT): mean unit normal, mean slope b and raw second moments E[b bᵀ].
// With n = 2^level the grid points are exactly the level-0 texel centres of the footprint, so the
// result equals that texel of the box-filtered chain; larger n converges to the continuous
// footprint integral (midpoint rule: O(1/n²) where the map is smooth, O(1/n) across creases).
import { PYRAMID_LAYOUT } from './momentPyramid.js';
import { checkSize } from './sampleLevel0.js';

/** The footprint [u0, v0, u1, v1] of texel (i, j) of `level` in a size² map. */
export function texelFootprint(size, level, i, j) {
  const side = 2 ** level / size;
  return [i * side, j * side, (i + 1) * side, (j + 1) * side];
}

function accumulate(map, [u0, v0, u1, v1], n, sums) {
  const b = [0, 0];
  const du = (u1 - u0) / n;
  const dv = (v1 - v0) / n;
  sums.fill(0);
  for (let sj = 0; sj < n; sj++) {
    const v = v0 + (sj + 0.5) * dv;
    for (let si = 0; si < n; si++) {
      map.slopeAt(u0 + (si + 0.5) * du, v, b);
      const inv = 1 / Math.sqrt(1 + b[0] * b[0] + b[1] * b[1]);
      sums[0] += b[0] * inv;
      sums[1] += b[1] * inv;
      sums[2] += inv;
      sums[3] += b[0];
      sums[4] += b[1];
      sums[5] += b[0] * b[0];
      sums[6] += b[1] * b[1];
      sums[7] += b[0] * b[1];
    }
  }
  for (let c = 0; c < sums.length; c++) sums[c] /= n * n;
  return sums;
}

/**
 * footprintAverage(map, [u0, v0, u1, v1], samplesPerAxis = 16) →
 * { normal: [x, y, z] (mean of unit normals, not renormalized), length: |normal|,
 *   slope: [bx, by], moments: [mxx, myy, mxy], samples: n² }, all in float64.
 */
export function footprintAverage(map, footprint, samplesPerAxis = 16) {
  if (!Number.isInteger(samplesPerAxis) || samplesPerAxis < 1) {
    throw new RangeError(`samplesPerAxis must be an integer >= 1, got ${String(samplesPerAxis)}`);
  }
  const s = accumulate(map, footprint, samplesPerAxis, new Float64Array(PYRAMID_LAYOUT.length));
  return {
    normal: [s[0], s[1], s[2]],
    length: Math.hypot(s[0], s[1], s[2]),
    slope: [s[3], s[4]],
    moments: [s[5], s[6], s[7]],
    samples: samplesPerAxis * samplesPerAxis,
  };
}

/**
 * groundTruthLevel(map, size, level, samplesPerAxis) → Float32Array(levelSize² · 8) in
 * PYRAMID_LAYOUT order: the supersampled truth for every texel of one level, for error maps.
 * Cost: levelSize² · samplesPerAxis² evaluations (size² · 16 at level 2 with n = 4).
 */
export function groundTruthLevel(map, size, level, samplesPerAxis) {
  checkSize(size);
  const w = PYRAMID_LAYOUT.length;
  const ls = Math.max(1, size >> level);
  const out = new Float32Array(ls * ls * w);
  const sums = new Float64Array(w);
  for (let j = 0; j < ls; j++) {
    for (let i = 0; i < ls; i++) {
      accumulate(map, texelFootprint(size, level, i, j), samplesPerAxis, sums);
      out.set(sums, (j * ls + i) * w);
    }
  }
  return out;
}
