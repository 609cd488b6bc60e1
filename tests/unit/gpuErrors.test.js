import { describe, expect, it } from 'vitest';
import { displayCodes, methodError, recommend } from '../../src/methods/advisor.js';
import { meanDisplayCodes } from '../../src/methods/displayBudgets.js';
import { thetaSamples } from '../../src/methods/errorMetrics.js';
import {
  domainExtra, domainInputs, domainSize, errorsFromValues, recommendWithErrors,
} from '../../src/methods/gpuErrors.js';
import { f82Coefficients, methodById, methodsOfKind } from '../../src/methods/methods.js';
import { contextFor } from '../../src/methods/rounding.js';
import { referenceFor, sceneById, SCENES } from '../../src/methods/scenes.js';

/** A small scene of the real shape: 2 index pairs × 5 angles, uniform in θ. */
const tiny = Object.freeze({
  id: 'tiny', label: 'Tiny', kind: 'dielectric', precision: 'fp32', weighting: 'uniform', thetaCount: 5,
  cases: Object.freeze([Object.freeze([1, 1.5]), Object.freeze([1.5, 1])]),
});

/** What a GPU would read back if it computed exactly like the JS twin in `precision`. */
function emulated(scene, method, precision) {
  const inputs = domainInputs(scene);
  const values = new Float32Array(domainSize(scene));
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  scene.cases.forEach((args, c) => {
    for (let i = 0; i < cos.length; i += 1) values[c * cos.length + i] = method.evaluate(precision, cos[i], ...args);
  });
  return { inputs, values };
}

/** The float64 reference at every sample, as plain numbers. */
function references(scene) {
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  const ref = referenceFor(scene.kind);
  return scene.cases.flatMap((args) => Array.from(cos, (c) => ref(c, ...args)));
}

describe('domainInputs and domainExtra', () => {
  it('lay the samples out case by case, angle by angle, in evaluateMethodsGpu\'s layout', () => {
    const inputs = domainInputs(tiny);
    expect(inputs).toBeInstanceOf(Float32Array);
    expect(inputs).toHaveLength(2 * 5 * 4);
    expect(Array.from(inputs.subarray(0, 4))).toEqual([1, 1, 1.5, 0]); // θ = 0: cos 1
    expect(Array.from(inputs.subarray(4 * 4, 5 * 4))).toEqual([0, 1, 1.5, 0]); // θ = 90°: cos exactly 0
    expect(Array.from(inputs.subarray(6 * 4, 7 * 4))).toEqual([Math.fround(Math.cos(Math.PI / 8)), 1.5, 1, 0]);
    const metal = sceneById('metal');
    const m = domainInputs(metal);
    expect(m).toHaveLength(domainSize(metal) * 4);
    const [n, k, f0] = metal.cases[1];
    const at = (1 * metal.thetaCount + 0) * 4;
    expect(Array.from(m.subarray(at, at + 4))).toEqual([1, n, k, f0].map(Math.fround));
  });

  it('give F82 its b from the case\'s float64 n, k, F0 and nothing to other methods', () => {
    const metal = sceneById('metal');
    const extra = domainExtra(metal, 'conductor-f82');
    const [n, k, f0] = metal.cases[2];
    expect(extra[(2 * metal.thetaCount + 7) * 4]).toBe(Math.fround(f82Coefficients(n, k, f0).b));
    expect(extra[(2 * metal.thetaCount + 7) * 4 + 1]).toBe(0);
    expect(domainExtra(metal, 'conductor-exact')).toBeNull();
    expect(domainExtra(sceneById('plastic'), 'exact-cg')).toBeNull();
  });
});

describe('errorsFromValues', () => {
  it('is exact for exact values, and a constant offset gives that offset as max, mean and RMS', () => {
    const ref = references(tiny);
    const zero = errorsFromValues(tiny, ref);
    expect(zero).toMatchObject({ count: 10, max: 0, mean: 0, rms: 0, nanCount: 0, maxCodes: 0, meanCodes: 0 });
    const offset = errorsFromValues(tiny, ref.map((r) => r + 0.001));
    expect(offset.max).toBeCloseTo(0.001, 12);
    expect(offset.mean).toBeCloseTo(0.001, 12);
    expect(offset.rms).toBeCloseTo(0.001, 12);
    // R is 1 at grazing and past the critical angle of 1.5 → 1 (41.8°): 1.001 is out of range
    // there and only there (90° from air; 45°, 67.5°, 90° from the glass).
    expect(offset.outOfRange).toBe(4);
  });

  it('weights the mean as the scene does and finds the angle and case of the max', () => {
    const ref = references(tiny);
    const values = ref.slice();
    values[7] += 0.2; // case 2 (1.5 → 1), θ = 45°
    const e = errorsFromValues(tiny, values);
    expect(e.max).toBeCloseTo(0.2, 12);
    expect(e.thetaAtMax).toBeCloseTo(Math.PI / 4, 15);
    expect(e.caseAtMax).toEqual([1.5, 1]);
    // Uniform trapezoid weights over 5 angles: 1/8 at the ends, 1/4 inside; halved per case.
    expect(e.mean).toBeCloseTo(0.2 * (0.25 / 2), 12);
    expect(e.rms).toBeCloseTo(Math.sqrt(0.04 * (0.25 / 2)), 12);
    expect(e.maxCodes).toBeCloseTo(displayCodes(values[7], ref[7]), 12);
  });

  it('counts NaN and Infinity as sweepDomain does: max ∞ at the first one, left out of the means', () => {
    const ref = references(tiny);
    const values = ref.slice();
    values[2] = NaN;
    values[8] = Infinity;
    values[3] += 0.01;
    const e = errorsFromValues(tiny, values);
    expect(e.nanCount).toBe(2);
    expect(e.max).toBe(Infinity);
    expect(e.maxCodes).toBe(Infinity);
    expect(e.thetaAtMax).toBeCloseTo(Math.PI / 4, 15); // sample 2: case 1, θ = 45°
    expect(e.caseAtMax).toEqual([1, 1.5]);
    // The finite samples' weights: 10 samples less samples 2 (1/4) and 8 (1/4), each halved.
    expect(e.mean).toBeCloseTo((0.01 * 0.25) / 2 / (1 - 0.25), 12);
  });

  it('reproduces methodError and meanDisplayCodes exactly when the values are the JS twin\'s', () => {
    const cases = [['plastic', 'exact-cg', 'fp32'], ['plastic', 'schlick-pow', 'fp16'], ['glass-inside', 'schlick-mul', 'fp32'],
      ['ice-water', 'exact-cg-literal', 'fp32'], ['metal', 'conductor-f82', 'fp32'], ['metal', 'conductor-exact', 'fp16']];
    for (const [sceneId, methodId, precision] of cases) {
      const scene = sceneById(sceneId);
      const method = methodById(methodId);
      const e = errorsFromValues(scene, emulated(scene, method, precision).values);
      const js = methodError(scene, method, precision);
      expect(e, `${sceneId} ${methodId} ${precision}`).toEqual({ ...js });
      expect(e.meanCodes).toBe(meanDisplayCodes(scene, method, precision));
    }
  });

  it('reads values that lost float32 precision in the read-back as the GPU gave them', () => {
    const scene = sceneById('plastic');
    const method = methodById('schlick-mul');
    const f64 = errorsFromValues(scene, Float64Array.from(emulated(scene, method, 'fp64').values));
    // The emulated float64 values went through a Float32Array: the error is float64's plus at most
    // half a float32 ulp of R ≤ 1.
    expect(Math.abs(f64.max - methodError(scene, method, 'fp64').max)).toBeLessThan(2 ** -24);
  });

  it('rejects a wrong number of values', () => {
    expect(() => errorsFromValues(tiny, new Float32Array(9))).toThrow(RangeError);
    expect(() => errorsFromValues(tiny, null)).toThrow(RangeError);
  });
});

describe('recommendWithErrors', () => {
  it('agrees with advisor.recommend when given the advisor\'s own errors', () => {
    for (const scene of SCENES) {
      const errors = Object.fromEntries(methodsOfKind(scene.kind).map((m) => [m.id, methodError(scene, m)]));
      const where = `${scene.label}, ${contextFor(scene.precision).label}`;
      const reversed = Object.fromEntries(methodsOfKind(scene.kind).map((m, i) => [m.id, 100 - i]));
      for (const costs of [{}, reversed]) {
        for (const budgetCodes of [0.5, 12.75]) {
          const mine = recommendWithErrors(scene, errors, costs, { budgetCodes, where, precision: scene.precision });
          expect(mine, `${scene.id} ${budgetCodes}`).toEqual(recommend(scene, costs, { budgetCodes }));
        }
      }
    }
  });

  it('decides from the errors it is given, and says where they came from', () => {
    const scene = sceneById('plastic');
    const errors = Object.fromEntries(methodsOfKind('dielectric').map((m) => [m.id, methodError(scene, m)]));
    // Pretend the GPU's Schlick-mul were perfect: it becomes the cheapest invisible method.
    errors['schlick-mul'] = errorsFromValues(scene, references(scene));
    const r = recommendWithErrors(scene, errors, {}, { where: 'Plastic, this GPU highp', precision: 'highp' });
    expect(r.methodId).toBe('schlick-mul');
    expect(r.precision).toBe('highp');
    expect(r.reason).toContain('"Plastic, this GPU highp"');
    // And a NaN anywhere fails a method under every budget.
    errors['schlick-mul'] = { ...errors['schlick-mul'], nanCount: 1, max: Infinity, maxCodes: Infinity };
    const nan = recommendWithErrors(scene, errors, {}, { budgetCodes: 25.5 });
    expect(nan.table.find((row) => row.methodId === 'schlick-mul').passes).toBe(false);
    expect(() => recommendWithErrors(scene, { 'exact-cg': errors['exact-cg'] })).toThrow(/no error given/);
  });
});
