import { describe, expect, it } from 'vitest';
import { contextFor, f16round, fp16, fp32, fp64, PRECISION_IDS } from '../../src/methods/rounding.js';
import { f82Coefficients, METHOD_IDS, methodById, methodsOfKind } from '../../src/methods/methods.js';
import {
  conductorNormalIncidence, criticalAngle, fresnelConductor, fresnelExact, fresnelSchlick,
  fresnelSchlickExp2, fresnelSchlickTIR,
} from '../../src/optics/fresnel.js';
import { linspace, sweepDomain } from '../../src/methods/errorMetrics.js';
import { absError, conductorR } from './oracle/fresnelOracle.js';

const DEG = Math.PI / 180;
const PAIRS = [[1, 1.33], [1, 1.5], [1, 2.4], [1.33, 1], [1.5, 1], [2.4, 1], [1.31, 1.333], [1.333, 1.31]];
const ANGLES = linspace(0, 89.9, 900);
const METALS = [[0.156, 3.602], [0.424, 2.472], [1.383, 1.916], [1.558, 7.712], [2.911, 3.089]];

/** Largest |method − reference| in fp64 over PAIRS × ANGLES, skipping ±0.5° around θc. */
function fp64Gap(id, reference) {
  const method = methodById(id);
  let gap = 0;
  for (const [nI, nT] of PAIRS) {
    const critical = criticalAngle(nI, nT);
    for (const t of ANGLES) {
      if (critical !== null && Math.abs(t * DEG - critical) < 0.5 * DEG) continue;
      const c = Math.cos(t * DEG);
      gap = Math.max(gap, Math.abs(method.evaluate('fp64', c, nI, nT) - reference(c, nI, nT)));
    }
  }
  return gap;
}

describe('rounding contexts', () => {
  it('float16 rounding matches known binary16 values', () => {
    expect(f16round(0.1)).toBe(0.0999755859375);
    expect(fp16.round(1 / 3)).toBe(0.333251953125);
    expect(fp16.round(65504)).toBe(65504); // largest finite half
    expect(fp16.round(65519)).toBe(65504);
    expect(fp16.round(65520)).toBe(Infinity); // halfway to 2^16 rounds to even: overflow
    expect(fp16.round(2 ** -14)).toBe(2 ** -14); // smallest normal
    expect(fp16.round(2 ** -24)).toBe(5.960464477539063e-8); // smallest subnormal
    expect(fp16.round(3 * 2 ** -26)).toBe(2 ** -24);
    expect(fp16.round(2 ** -25)).toBe(0); // tie between 0 and 2^-24: to even
    expect(fp16.round(1.5 * 2 ** -24)).toBe(2 ** -23);
  });
  it('every operation rounds: 1 + 2^-11 is 1 in half, 1 + 2^-10 is not', () => {
    expect(fp16.add(1, 2 ** -11)).toBe(1);
    expect(fp16.add(1, 2 ** -10)).toBe(1 + 2 ** -10);
    expect(fp16.mul(300, 300)).toBe(Infinity);
    expect(fp32.add(1, 2 ** -24)).toBe(1);
    expect(fp32.round(0.1)).toBe(0.10000000149011612);
    expect(fp32.sqrt(2)).toBe(Math.fround(Math.SQRT2));
    expect(fp64.add(0.1, 0.2)).toBe(0.1 + 0.2);
  });
  it('pow follows GLSL: NaN for a negative base, 0 for pow(0, 5)', () => {
    for (const id of PRECISION_IDS) {
      const P = contextFor(id);
      expect(P.pow(-1e-3, 5)).toBeNaN();
      expect(P.pow(0, 5)).toBe(0);
      expect(P.pow(0.5, 5)).toBe(1 / 32);
    }
    expect(fp16.exp2(-30)).toBe(0); // below the subnormal range
  });
  it('contextFor accepts names and contexts and rejects anything else', () => {
    expect(contextFor('fp32')).toBe(fp32);
    expect(contextFor(fp16)).toBe(fp16);
    expect(() => contextFor('fp8')).toThrow(RangeError);
    expect(() => contextFor({ name: 'fp32' })).toThrow(RangeError);
  });
});

describe('method table', () => {
  it('lists seven dielectric and three conductor methods with cost hints', () => {
    expect(methodsOfKind('dielectric').map((m) => m.id)).toEqual([
      'exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-pow', 'schlick-mul', 'schlick-tir', 'schlick-exp2',
    ]);
    expect(methodsOfKind('conductor').map((m) => m.id)).toEqual(['conductor-exact', 'conductor-schlick', 'conductor-f82']);
    for (const id of METHOD_IDS) expect(methodById(id).cost.static).toBeGreaterThan(0);
    expect(() => methodById('nope')).toThrow(RangeError);
  });
});

describe('methods in float64 agree with fresnel.js', () => {
  it('exact c/g (safe order) matches fresnelExact to 1e-12 away from the critical angle', () => {
    expect(fp64Gap('exact-cg', fresnelExact)).toBeLessThan(1e-12);
  });
  it('the literal c/g and the s/p forms match too', () => {
    expect(fp64Gap('exact-cg-literal', fresnelExact)).toBeLessThan(1e-12);
    expect(fp64Gap('exact-sp', fresnelExact)).toBeLessThan(1e-12);
  });
  it('the Schlick variants match fresnel.js Schlick, Schlick-TIR and exp2', () => {
    expect(fp64Gap('schlick-pow', fresnelSchlick)).toBeLessThan(1e-14);
    expect(fp64Gap('schlick-mul', fresnelSchlick)).toBeLessThan(1e-15);
    expect(fp64Gap('schlick-tir', fresnelSchlickTIR)).toBeLessThan(1e-14); // fresnel.js: double-double g²
    expect(fp64Gap('schlick-exp2', fresnelSchlickExp2)).toBeLessThan(1e-15);
  });
  it('exact conductor matches fresnelConductor to 1e-13', () => {
    const method = methodById('conductor-exact');
    for (const [n, k] of METALS) {
      for (const t of ANGLES) {
        const c = Math.cos(t * DEG);
        expect(Math.abs(method.evaluate('fp64', c, n, k) - fresnelConductor(c, n, k))).toBeLessThan(1e-13);
      }
    }
  });
  it('conductor Schlick is F0 + (1 − F0)(1 − c)^5 with the exact F0', () => {
    const [n, k] = METALS[0];
    const f0 = conductorNormalIncidence(n, k);
    const method = methodById('conductor-schlick');
    expect(method.evaluate('fp64', 1, n, k)).toBeCloseTo(f0, 15);
    expect(method.evaluate('fp64', 0.3, n, k)).toBeCloseTo(f0 + (1 - f0) * 0.7 ** 5, 15);
    expect(method.evaluate('fp64', 0.3, n, k, 0.5)).toBeCloseTo(0.5 + 0.5 * 0.7 ** 5, 15);
  });
  it('F82-tint is exact at 0°, at cos = 1/7 and at grazing; aluminium 650 nm error 0.022', () => {
    const method = methodById('conductor-f82');
    for (const [n, k] of METALS) {
      const { f0, f82, tint } = f82Coefficients(n, k);
      expect(absError(f82, conductorR(1 / 7, n, k))).toBeLessThan(1e-12); // the 50-digit oracle at cos = 1/7
      expect(method.evaluate('fp64', 1, n, k)).toBeCloseTo(f0, 14);
      expect(method.evaluate('fp64', 1 / 7, n, k)).toBeCloseTo(f82, 14);
      expect(method.evaluate('fp64', 0, n, k)).toBe(1);
      expect(tint * (f0 + (1 - f0) * (6 / 7) ** 5)).toBeCloseTo(f82, 15);
    }
    const al = sweepDomain({
      evaluate: (c, n, k) => method.evaluate('fp64', c, n, k),
      reference: fresnelConductor,
      cases: [[1.558, 7.712]],
    });
    expect(al.max).toBeCloseTo(0.0219, 4); // computed against the exact conductor formula; Schlick: 0.130
    expect(al.thetaAtMax / DEG).toBeCloseTo(86.6, 0);
  });
});

describe('failure modes appear without being programmed in', () => {
  it('the lecture order gives R = 1 for matched media near grazing in float32; the safe order gives 0', () => {
    const literal = methodById('exact-cg-literal');
    const safe = methodById('exact-cg');
    expect(literal.evaluate('fp32', 1e-4, 1.333, 1.333)).toBe(1);
    expect(safe.evaluate('fp32', 1e-4, 1.333, 1.333)).toBe(0);
    expect(literal.evaluate('fp32', 0.5, 1.333, 1.333)).toBeLessThan(1e-6); // fine away from grazing
    expect(literal.evaluate('fp64', 1e-4, 1.333, 1.333)).toBeLessThan(1e-12); // float64 only below 1.2e-8
    expect(literal.evaluate('fp64', 1e-9, 1.333, 1.333)).toBe(1);
    // float16: 1 + c² is 1 for c² below 2^-11, so R = 1 past 88.7°; at 88° it is already 0.003
    expect(literal.evaluate('fp16', Math.cos(89 * DEG), 1, 1)).toBe(1);
    expect(literal.evaluate('fp16', Math.cos(88 * DEG), 1, 1)).toBeCloseTo(0.00306, 5);
  });
  it('nearly matched indices exact in float32 (1 and 1 + 2^-22): the safe order keeps full accuracy', () => {
    const n = 1 + 2 ** -22;
    const gap = (id, c, nI, nT) => Math.abs(methodById(id).evaluate('fp32', c, nI, nT) - fresnelExact(c, nI, nT));
    expect(gap('exact-cg', 1e-4, 1, n)).toBeLessThan(2e-7);
    expect(gap('exact-cg-literal', 1e-4, 1, n)).toBeGreaterThan(3e-3); // 1 + c² loses c² = 1e-8
    expect(gap('exact-cg', 1e-3, n, 1)).toBeLessThan(2e-8);
    expect(gap('exact-cg-literal', 1e-3, n, 1)).toBeGreaterThan(7e-3);
  });
  it('Schlick has no total internal reflection: off by 0.959 from glass to air', () => {
    for (const id of ['schlick-pow', 'schlick-mul']) {
      const s = sweepDomain({
        evaluate: (c, nI, nT) => methodById(id).evaluate('fp32', c, nI, nT),
        reference: fresnelExact,
        cases: [[1.5, 1]],
        thetaCount: 9001,
      });
      expect(s.max).toBeCloseTo(0.959, 3);
      expect(s.thetaAtMax / DEG).toBeCloseTo(41.81, 1);
    }
    expect(methodById('schlick-tir').evaluate('fp32', Math.cos(45 * DEG), 1.5, 1)).toBe(1);
  });
  it('float16 exact forms are off by 0.2 near the critical angle; float32 by < 1e-4', () => {
    const near = (id, precision) => sweepDomain({
      evaluate: (c, nI, nT) => methodById(id).evaluate(precision, c, nI, nT),
      reference: fresnelExact,
      cases: [[1.5, 1]],
      thetaCount: 9001,
    });
    const cg16 = near('exact-cg', 'fp16');
    expect(cg16.max).toBeGreaterThan(0.15);
    expect(cg16.max).toBeLessThan(0.3);
    expect(cg16.thetaAtMax / DEG).toBeCloseTo(41.8, 0);
    expect(near('exact-sp', 'fp16').max).toBeGreaterThan(0.05);
    expect(near('exact-cg', 'fp32').max).toBeLessThan(1e-4);
    // away from it, float16 exact is within a few 1e-3 (air to glass)
    const outside = sweepDomain({
      evaluate: (c, nI, nT) => methodById('exact-cg').evaluate('fp16', c, nI, nT),
      reference: fresnelExact,
      cases: [[1, 1.5]],
    });
    expect(outside.max).toBeLessThan(3e-3);
    expect(outside.max).toBeGreaterThan(1e-4);
  });
  it('pow of a negative base is NaN when cos overshoots 1; the multiply-only form is not', () => {
    const c = Math.fround(1 + 2 ** -23);
    expect(methodById('schlick-pow').evaluate('fp32', c, 1, 1.5)).toBeNaN();
    expect(methodById('schlick-mul').evaluate('fp32', c, 1, 1.5)).toBeCloseTo(0.04, 6);
    expect(methodById('schlick-exp2').evaluate('fp32', c, 1, 1.5)).toBeCloseTo(0.04, 3); // three.js saturates
    expect(methodById('schlick-mul').evaluate('fp32', -0.05, 1, 1.5)).toBeGreaterThan(1); // no clamp: 1.265
  });
});
