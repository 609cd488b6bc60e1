// Fast float32 → binary16 rounding for whole mip chains. @petamoriken/float16's f16round costs
// about 34 ns a value in Node 20 and its setFloat16 about 2 µs (measured here), i.e. seconds for
// the ~30 million values of six 1024² chains. roundHalfArray rounds with one float64 addition
// (below) and halfBits builds the bit pattern from the float32 one; both do IEEE 754 rounding to
// nearest, ties to even, with subnormals and overflow to ±Infinity. Their inputs are float32
// values, so the rounding is single, and tests check both against f16round.

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);

/** The binary16 bit pattern nearest to the float32 whose bit pattern is b. */
export function halfBitsOfFloat32Bits(b) {
  const sign = (b >>> 16) & 0x8000;
  const exp = (b >>> 23) & 0xff;
  const mant = b & 0x7fffff;
  if (exp === 0xff) return sign | 0x7c00 | (mant ? 0x200 : 0); // Infinity, NaN
  const e = exp - 112; // rebias 127 → 15
  if (e >= 31) return sign | 0x7c00;
  if (e <= 0) {
    // Subnormal half: value = m · 2^−24, m = (1.mant) · 2^(e − 1 + 10 − 23) → shift right by 14 − e.
    if (e < -10) return sign;
    const full = mant | 0x800000;
    const shift = 14 - e;
    const half = 1 << (shift - 1);
    let m = full >>> shift;
    const rem = full & ((1 << shift) - 1);
    if (rem > half || (rem === half && (m & 1))) m++;
    return sign | m; // m = 0x400 carries into the smallest normal, which is the right encoding
  }
  let h = sign | (e << 10) | (mant >>> 13);
  const rem = mant & 0x1fff;
  if (rem > 0x1000 || (rem === 0x1000 && (h & 1))) h++; // a carry may reach the exponent or Infinity
  return h;
}

/** The binary16 bit pattern nearest to x (x is first rounded to float32). */
export function halfBits(x) {
  f32[0] = x;
  return halfBitsOfFloat32Bits(u32[0]);
}

/** The value of a binary16 bit pattern. */
export function halfValue(h) {
  const sign = h & 0x8000 ? -1 : 1;
  const e = (h >>> 10) & 0x1f;
  const m = h & 0x3ff;
  if (e === 0) return sign * m * 2 ** -24;
  if (e === 31) return m ? NaN : sign * Infinity;
  return sign * (1 + m / 1024) * 2 ** (e - 15);
}

// Rounding a float64 to a multiple of q with ties to even: (x + C) − C with C = 1.5 · 2^52 · q,
// because the sum stays in the binade of C, whose ulp is q, and float64 addition rounds to
// nearest even (IEEE 754 §4.3.1); C/q = 3 · 2^51 is even, so ties go to even multiples of q.
// q is the binary16 ulp for the input's float32 exponent: 2^(e − 10), or 2^−24 below 2^−14.
const MAGIC = new Float64Array(256);
for (let exp = 0; exp < 256; exp++) MAGIC[exp] = 1.5 * 2 ** (52 + Math.max(exp - 127, -14) - 10);

/** Rounds every element of a Float32Array to binary16 in place (same results as f16round). */
export function roundHalfArray(data) {
  const bits = new Uint32Array(data.buffer, data.byteOffset, data.length);
  for (let i = 0; i < data.length; i++) {
    const x = data[i];
    const exp = (bits[i] >>> 23) & 0xff;
    if (exp === 0xff) continue; // ±Infinity, NaN
    const C = MAGIC[exp];
    const y = x + C - C;
    if (y > 65504) data[i] = Infinity;
    else if (y < -65504) data[i] = -Infinity;
    else data[i] = y === 0 ? x * 0 : y; // keep the sign of zero
  }
  return data;
}
