// Method ids ↔ the integer indices of fm_evaluate in shaders/fresnelMethods.glsl, and the GLSL
// function of each method. The indices are the order of METHODS in src/methods/methods.js; the
// GLSL selector hard-codes them, and tests/unit/methodIndex.test.js checks the two agree.
import { METHOD_IDS, methodById } from '../methods/methods.js';

/** { 'exact-cg': 0, 'exact-cg-literal': 1, ..., 'conductor-f82': 9 } */
export const METHOD_INDEX = Object.freeze(Object.fromEntries(METHOD_IDS.map((id, i) => [id, i])));

/** The fm_evaluate index of a method id; throws RangeError on an unknown id. */
export function methodIndex(id) {
  methodById(id); // throws on an unknown id
  return METHOD_INDEX[id];
}

/** The method id at an fm_evaluate index; throws RangeError outside 0..count − 1. */
export function methodIdAt(index) {
  if (!Number.isInteger(index) || index < 0 || index >= METHOD_IDS.length) {
    throw new RangeError(`no Fresnel method at index ${String(index)}`);
  }
  return METHOD_IDS[index];
}

/** The GLSL function of a method: 'exact-cg-literal' → 'fm_exact_cg_literal'. */
export function glslFunctionName(id) {
  methodById(id);
  return `fm_${id.replaceAll('-', '_')}`;
}

/** GLSL precision qualifiers the GPU evaluation accepts, and the JS context each one emulates. */
export const GPU_PRECISIONS = Object.freeze(['highp', 'mediump']);
export const JS_TWIN_OF = Object.freeze({ highp: 'fp32', mediump: 'fp16' });
