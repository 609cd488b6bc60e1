import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { GPU_PRECISIONS, glslFunctionName, JS_TWIN_OF, METHOD_INDEX, methodIdAt, methodIndex } from '../../src/gl/methodIndex.js';
import { methodFragmentSource } from '../../src/gl/evaluateMethodsGpu.js';
import { METHOD_IDS, methodById } from '../../src/methods/methods.js';

const glsl = readFileSync('shaders/fresnelMethods.glsl', 'utf8');

/** Each `float name(params) { body }` of a GLSL file: { name, params, body }. */
function glslFunctions(source) {
  const out = {};
  const head = /^float (\w+)\(([^)]*)\) \{$/gm;
  let match;
  while ((match = head.exec(source))) {
    const end = source.indexOf('\n}\n', match.index);
    out[match[1]] = { params: match[2].split(',').map((p) => p.trim()), body: source.slice(match.index, end) };
  }
  return out;
}

describe('method indices', () => {
  it('follow the order of METHODS in methods.js and invert', () => {
    expect(Object.keys(METHOD_INDEX)).toEqual([...METHOD_IDS]);
    METHOD_IDS.forEach((id, i) => {
      expect(methodIndex(id)).toBe(i);
      expect(methodIdAt(i)).toBe(id);
    });
    expect(METHOD_INDEX['exact-cg']).toBe(0);
    expect(METHOD_INDEX['conductor-f82']).toBe(9);
    expect(() => methodIndex('nope')).toThrow(RangeError);
    expect(() => methodIdAt(METHOD_IDS.length)).toThrow(RangeError);
    expect(glslFunctionName('exact-cg-literal')).toBe('fm_exact_cg_literal');
    expect(GPU_PRECISIONS).toEqual(['highp', 'mediump']);
    expect(JS_TWIN_OF).toEqual({ highp: 'fp32', mediump: 'fp16' });
  });

  it('match the selector in shaders/fresnelMethods.glsl, one branch per method', () => {
    const branches = [...glsl.matchAll(/if \(method == (\d+)\) return (fm_\w+)\(/g)].map((m) => [Number(m[1]), m[2]]);
    expect(branches).toEqual(METHOD_IDS.map((id, i) => [i, glslFunctionName(id)]));
  });
});

describe('GLSL twins', () => {
  const fns = glslFunctions(glsl);
  it('define every method with (c, nI, nT) for dielectrics and (c, n, k, f0, b) for conductors', () => {
    for (const id of METHOD_IDS) {
      const fn = fns[glslFunctionName(id)];
      expect(fn, id).toBeDefined();
      const expected = methodById(id).kind === 'dielectric'
        ? ['float ci', 'float nI', 'float nT']
        : ['float c', 'float n', 'float k', 'float f0', 'float b'];
      expect(fn.params, id).toEqual(expected);
    }
  });
  it('clamp only where the JS clamps (three.js exp2 saturates c; F82 clamps as Cycles does)', () => {
    const clamping = METHOD_IDS.filter((id) => fns[glslFunctionName(id)].body.includes('clamp('));
    expect(clamping).toEqual(['schlick-exp2', 'conductor-f82']);
    // No precision qualifiers: the includer's default precision (highp or mediump) applies to all.
    expect(glsl.replace(/\/\/.*$/gm, '')).not.toMatch(/\b(highp|mediump|lowp)\b/);
  });
  it('keep the lecture order 1 + c² − m² in the literal form and the safe g² elsewhere', () => {
    expect(fns.fm_exact_cg_literal.body).toContain('float g2 = 1.0 + c * c - m * m;');
    // The safe g² is fresnel.glsl's, shared through #include <fresnel>, not a copy.
    const shared = glslFunctions(readFileSync('shaders/fresnel.glsl', 'utf8'));
    expect(glsl).toContain('#include <fresnel>');
    expect(shared.cosTransmittedSq.body).toContain('((nT - nI) / nT) * ((nT + nI) / nT) + c * c');
    expect(shared.fresnelExactRaw.body).toContain('cosTransmittedSq(ci, nI, nT)');
    expect(fns.fm_exact_cg.body).toContain('fresnelExactRaw(ci, nI, nT)');
    expect(fns.fm_schlick_tir.body).toContain('cosTransmittedSq(ci, nI, nT)');
    expect(fns.fm_schlick_pow.body).toContain('pow(1.0 - ci, 5.0)');
  });
});

describe('methodFragmentSource', () => {
  it('is the same source under highp or mediump, calling fm_evaluate with the method index', () => {
    const high = methodFragmentSource('exact-sp', 'highp');
    const medium = methodFragmentSource('exact-sp', 'mediump');
    expect(high.startsWith('#version 300 es\nprecision highp float;')).toBe(true);
    expect(medium.startsWith('#version 300 es\nprecision mediump float;')).toBe(true);
    expect(medium.replace('mediump float', 'highp float')).toBe(high);
    expect(high).toContain('fm_evaluate(2, texelFetch(uInputs, p, 0), texelFetch(uExtra, p, 0))');
    expect(high).toContain('float fm_exact_sp(float ci, float nI, float nT)');
    expect(high).not.toContain('#include');
    expect(() => methodFragmentSource('exact-sp', 'lowp')).toThrow(RangeError);
    expect(() => methodFragmentSource('nope', 'highp')).toThrow(RangeError);
  });
});
