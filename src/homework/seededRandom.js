// @ts-check
// Seeded randomness for homework: two students with different seeds get different numbers, and
// the same seed gives the same numbers again (when the answers are checked). A seed is any text;
// it is hashed to 32 bits (FNV-1a) and drives mulberry32, a small generator with a full 2^32
// period (Tommy Ettinger's public-domain design) that is plenty for picking parameters.

/**
 * 32-bit FNV-1a hash of a string (Fowler, Noll and Vo).
 * @param {unknown} text
 */
export function hashSeed(text) {
  let h = 0x811c9dc5;
  for (const char of String(text)) {
    h ^= char.codePointAt(0) ?? 0; // a string's characters all have a code point
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h >>> 0;
}

/**
 * A generator of numbers in [0, 1) from a seed (text or number); pick(list) takes one element.
 * @param {unknown} seed
 */
export function seededRandom(seed) {
  let a = typeof seed === 'number' ? seed >>> 0 : hashSeed(seed);
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  /**
   * @template T
   * @param {readonly T[]} list
   * @returns {T}
   */
  const pick = (list) => list[Math.floor(next() * list.length)];
  return { next, pick };
}

/** A fresh seed for a student: 8 characters from the crypto generator where there is one. */
export function newSeed() {
  const bytes = new Uint8Array(8);
  if (globalThis.crypto?.getRandomValues) globalThis.crypto.getRandomValues(bytes);
  else for (let i = 0; i < bytes.length; i += 1) bytes[i] = Math.floor(Math.random() * 256);
  return Array.from(bytes, (b) => 'abcdefghjkmnpqrstuvwxyz23456789'[b % 31]).join('');
}
