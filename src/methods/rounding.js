// Arithmetic contexts: the same method code evaluated in float64, float32 or float16.
// Each operation is done in float64 and rounded once to the target format. For + − × ÷ and sqrt
// that equals the correctly rounded result of the target format, because float64 has more than
// 2p + 2 significand bits for p = 24 and p = 11 (Figueroa, "When is double rounding innocuous?",
// SIGNUM Newsletter 30(3), 1995). float32 rounding is Math.fround; float16 is @petamoriken/float16's
// f16round (IEEE 754 binary16, round-to-nearest-even, subnormals, overflow to ±Infinity).
// Rounding after every operation models a GPU, which rounds each instruction's result to its format.
// A context's label (its name in words) is the catalogue's ("methods": precision.<name>).
import { f16round } from '@petamoriken/float16';
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';

const t = messages('methods', english);

/**
 * An arithmetic context: each operation done in float64 and rounded once to the context's format.
 * @typedef {Readonly<{
 *   name: string, label: string, bits: number, round: (x: number) => number,
 *   add: (a: number, b: number) => number, sub: (a: number, b: number) => number,
 *   mul: (a: number, b: number) => number, div: (a: number, b: number) => number,
 *   sqrt: (a: number) => number, pow: (x: number, y: number) => number, exp2: (a: number) => number,
 *   clamp: (x: number, lo: number, hi: number) => number,
 * }>} Context
 */

const identity = (/** @type {number} */ x) => x;

/**
 * GLSL ES 3.00 §8.2: pow(x, y) is undefined for x < 0 and "inherits its precision from
 * exp2(y·log2 x)", which is how GPUs evaluate it: a negative base gives NaN there (log2 of a
 * negative number; Mesa does so, gl-transitions PR #252), unlike Math.pow(−0.1, 5). The log2, the product and the exp2 are each rounded.
 * @param {(x: number) => number} round
 * @returns {(x: number, y: number) => number}
 */
function makePow(round) {
  return (x, y) => {
    if (Number.isNaN(x) || x < 0) return NaN;
    return round(2 ** round(y * round(Math.log2(x))));
  };
}

/**
 * @param {string} name
 * @param {(x: number) => number} round
 * @param {number} bits
 * @returns {Context}
 */
function makeContext(name, round, bits) {
  return Object.freeze({
    name,
    /** The format in words, float32 (highp), in the page's language. */
    get label() { return t(`precision.${name}`); },
    /** Significand bits including the hidden one (53, 24, 11). */
    bits,
    /** Rounds a float64 value (an input, a uniform, a literal) to this format. */
    round,
    add: (a, b) => round(a + b),
    sub: (a, b) => round(a - b),
    mul: (a, b) => round(a * b),
    div: (a, b) => round(a / b),
    sqrt: (a) => round(Math.sqrt(a)),
    pow: makePow(round),
    exp2: (a) => round(2 ** a),
    // clamp returns one of its (already rounded) arguments: no rounding needed. NaN stays NaN,
    // as min/max with a NaN operand do on most GPUs (GLSL leaves it undefined).
    clamp: (x, lo, hi) => (Number.isNaN(x) ? NaN : Math.min(hi, Math.max(lo, x))),
  });
}

/** float64: the reference arithmetic, no rounding beyond JavaScript's own. */
export const fp64 = makeContext('fp64', identity, 53);
/** float32: GLSL highp on every WebGL2 GPU. */
export const fp32 = makeContext('fp32', Math.fround, 24);
/** float16: GLSL mediump where the GPU really runs it at half precision (many phones). */
export const fp16 = makeContext('fp16', f16round, 11);

export const PRECISIONS = Object.freeze({ fp64, fp32, fp16 });
export const PRECISION_IDS = Object.freeze(Object.keys(PRECISIONS));

/**
 * The context for 'fp64' | 'fp32' | 'fp16', or the context itself; throws on anything else.
 * @param {unknown} precision
 * @returns {Context}
 */
export function contextFor(precision) {
  switch (precision) {
    case fp64: case 'fp64': return fp64;
    case fp32: case 'fp32': return fp32;
    case fp16: case 'fp16': return fp16;
    default: throw new RangeError(`precision must be one of ${PRECISION_IDS.join(', ')}, got ${String(precision)}`);
  }
}

export { f16round };
