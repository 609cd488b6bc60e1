// Level 0 of a normal map: the exact unit normal point-sampled at every texel centre.
// Layout: row-major, texel (i, j) at index (j·size + i)·components, centre u = (i + ½)/size,
// v = (j + ½)/size. Row 0 is v ≈ 0, which is where texSubImage2D puts it (UNPACK_FLIP_Y_WEBGL is
// false by default). Values are the normal's x, y, z in [−1, 1]
// (not the c = n/2 + ½ colour encoding; storagePrecision.js does that), and alpha = 1 when
// components = 4.

/** Throws unless size is a power of two in [1, 4096]. The panel uses 64 to 1024. */
export function checkSize(size) {
  if (!Number.isInteger(size) || size < 1 || size > 4096 || (size & (size - 1)) !== 0) {
    throw new RangeError(`size must be a power of two in [1, 4096], got ${String(size)}`);
  }
  return size;
}

/** sampleLevel0(map, size, { components = 3 }) → Float32Array(size² · components). */
export function sampleLevel0(map, size, { components = 3 } = {}) {
  checkSize(size);
  if (components !== 3 && components !== 4) throw new RangeError(`components must be 3 or 4, got ${components}`);
  const data = new Float32Array(size * size * components);
  const n = [0, 0, 0];
  for (let j = 0; j < size; j++) {
    const v = (j + 0.5) / size;
    for (let i = 0; i < size; i++) {
      map.normalAt((i + 0.5) / size, v, n);
      const o = (j * size + i) * components;
      data[o] = n[0];
      data[o + 1] = n[1];
      data[o + 2] = n[2];
      if (components === 4) data[o + 3] = 1;
    }
  }
  return data;
}

/**
 * The level-0 slopes b = (n_x/n_z, n_y/n_z) at the same texel centres: Float32Array(size² · 2),
 * straight from the analytic slope (not divided out of a float32 normal).
 */
export function sampleSlopes(map, size) {
  checkSize(size);
  const data = new Float32Array(size * size * 2);
  const b = [0, 0];
  for (let j = 0; j < size; j++) {
    const v = (j + 0.5) / size;
    for (let i = 0; i < size; i++) {
      map.slopeAt((i + 0.5) / size, v, b);
      data[2 * (j * size + i)] = b[0];
      data[2 * (j * size + i) + 1] = b[1];
    }
  }
  return data;
}
