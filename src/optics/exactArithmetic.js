// Error-free transformations (Knuth's TwoSum, Dekker's TwoProduct with Veltkamp splitting).
// They let the optics code form a small difference of large products without losing digits:
// a + b = s + e and a * b = p + e hold exactly in float64.
// Source: Ogita, Rump & Oishi, "Accurate sum and dot product", SIAM J. Sci. Comput. 26(6), 2005.

const SPLITTER = 134217729; // 2^27 + 1

/**
 * Exact sum: returns [s, e] with s = fl(a + b) and a + b = s + e.
 * @param {number} a
 * @param {number} b
 * @returns {[number, number]}
 */
export function twoSum(a, b) {
  const s = a + b;
  const bb = s - a;
  const e = (a - (s - bb)) + (b - bb);
  return [s, e];
}

/**
 * @param {number} a
 */
function split(a) {
  const t = SPLITTER * a;
  const hi = t - (t - a);
  return [hi, a - hi];
}

/**
 * Exact product: returns [p, e] with p = fl(a * b) and a * b = p + e.
 * @param {number} a
 * @param {number} b
 * @returns {[number, number]}
 */
export function twoProduct(a, b) {
  const p = a * b;
  const [ah, al] = split(a);
  const [bh, bl] = split(b);
  const e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
  return [p, e];
}

/**
 * Sum of exact terms given as [hi, lo] pairs, accumulated in double-double and rounded once.
 * Cancellation between the terms costs no digits beyond about 2^-100 of the largest term.
 * @param {readonly (readonly [number, number])[]} pairs
 */
export function sumPairs(pairs) {
  let hi = 0;
  let lo = 0;
  for (const [a, b] of pairs) {
    const [s, e] = twoSum(hi, a);
    hi = s;
    lo += e + b;
  }
  const [s, e] = twoSum(hi, lo);
  return s + e;
}
