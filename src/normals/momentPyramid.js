// The linear moment pyramid every technique's mip chain is derived from.
// Per texel, 8 float32 values (PYRAMID_LAYOUT): the mean normal N_a = (nx, ny, nz), the mean slope
// B = (bx, by) and the raw second slope moments M = (mxx, myy, mxy) = E[bx²], E[by²], E[bx·by],
// with b = (n_x/n_z, n_y/n_z) per level-0 texel (Olano & Baker, "LEAN Mapping", I3D 2010).
// All eight are plain means, so a 2×2 box reduction of level L gives level L + 1 exactly
// (up to float32 rounding) and equals the mean over the level-0 footprint: the box filter the GL
// spec recommends for glGenerateMipmap ("a box filter is recommended", glGenerateMipmap reference
// page). Level count = log2(size) + 1, down to 1×1.
import { checkSize } from './sampleLevel0.js';

export const PYRAMID_LAYOUT = Object.freeze(['nx', 'ny', 'nz', 'bx', 'by', 'mxx', 'myy', 'mxy']);
const W = PYRAMID_LAYOUT.length;

export function levelCount(size) {
  checkSize(size);
  return Math.log2(size) + 1;
}

export function levelSize(size, level) {
  return Math.max(1, size >> level);
}

/** Texels in a full chain: Σ 4^k for k = 0..log2(size), i.e. (4·size² − 1)/3. */
export function chainTexelCount(size) {
  let total = 0;
  for (let l = 0; l < levelCount(size); l++) total += levelSize(size, l) ** 2;
  return total;
}

/** Level-0 moments from unit normals (components 3 or 4 per texel). */
function momentsOfLevel0(normals, size, components) {
  const data = new Float32Array(size * size * W);
  for (let t = 0; t < size * size; t++) {
    const x = normals[t * components];
    const y = normals[t * components + 1];
    const z = normals[t * components + 2];
    if (!(z > 0)) throw new RangeError(`texel ${t}: n_z must be > 0 for a tangent-space slope, got ${z}`);
    const bx = x / z;
    const by = y / z;
    const o = t * W;
    data[o] = x;
    data[o + 1] = y;
    data[o + 2] = z;
    data[o + 3] = bx;
    data[o + 4] = by;
    data[o + 5] = bx * bx;
    data[o + 6] = by * by;
    data[o + 7] = bx * by;
  }
  return data;
}

/** 2×2 box reduction of a W-wide level (sums in float64, one float32 rounding on store). */
export function reduceLevel(src, srcSize, width = W) {
  const size = srcSize >> 1;
  const dst = new Float32Array(size * size * width);
  for (let j = 0; j < size; j++) {
    const r0 = 2 * j * srcSize;
    const r1 = r0 + srcSize;
    for (let i = 0; i < size; i++) {
      const a = (r0 + 2 * i) * width;
      const b = (r1 + 2 * i) * width;
      const o = (j * size + i) * width;
      for (let c = 0; c < width; c++) {
        dst[o + c] = 0.25 * (src[a + c] + src[a + width + c] + src[b + c] + src[b + width + c]);
      }
    }
  }
  return dst;
}

/**
 * buildMomentPyramid(normals, size, { components = 3 }) → [{ level, size, data }] from level 0
 * to 1×1, data = Float32Array(size² · 8) in PYRAMID_LAYOUT order.
 */
export function buildMomentPyramid(normals, size, { components = 3 } = {}) {
  checkSize(size);
  if (normals.length !== size * size * components) {
    throw new RangeError(`expected ${size * size * components} values for ${size}² × ${components}, got ${normals.length}`);
  }
  const levels = [{ level: 0, size, data: momentsOfLevel0(normals, size, components) }];
  for (let l = 1; l < levelCount(size); l++) {
    const prev = levels[l - 1];
    levels.push({ level: l, size: prev.size >> 1, data: reduceLevel(prev.data, prev.size) });
  }
  return levels;
}
