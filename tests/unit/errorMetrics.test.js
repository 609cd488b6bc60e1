import { describe, expect, it } from 'vitest';
import {
  absoluteError, cosTheta, createAccumulator, errorStats, linspace, sweepDomain, thetaSamples,
} from '../../src/methods/errorMetrics.js';

const HALF_PI = Math.PI / 2;

function samplesOf(errorOf, count, weighting) {
  const { theta, weight } = thetaSamples(count, weighting);
  return Array.from(theta, (t, i) => ({ value: 0.5 + errorOf(t), reference: 0.5, theta: t, weight: weight[i] }));
}

describe('errorStats on known functions', () => {
  it('a constant offset gives max = mean = rms = the offset, whatever the weights', () => {
    for (const weighting of ['uniform', 'cosine']) {
      const s = errorStats(samplesOf(() => 0.01, 91, weighting));
      expect(s.max).toBeCloseTo(0.01, 15);
      expect(s.mean).toBeCloseTo(0.01, 15);
      expect(s.rms).toBeCloseTo(0.01, 15);
      expect(s.count).toBe(91);
      expect(s.nanCount).toBe(0);
      expect(s.outOfRange).toBe(0);
    }
  });
  it('error = θ (uniform): max π/2 at 90°, mean π/4, rms π/(2√3)', () => {
    const s = errorStats(samplesOf((t) => t / 10, 2001, 'uniform')); // keep values in [0, 1]
    expect(s.max).toBeCloseTo(HALF_PI / 10, 15);
    expect(s.thetaAtMax).toBe(HALF_PI);
    expect(s.mean).toBeCloseTo(Math.PI / 40, 12); // trapezoid rule is exact for a linear function
    expect(s.rms).toBeCloseTo(Math.PI / (20 * Math.sqrt(3)), 6);
  });
  it('weighted means: sin²θ under 2 cosθ sinθ dθ is 1/2; sin⁴θ is 3/8 uniform and 1/3 cosine-weighted', () => {
    const cosine = errorStats(samplesOf((t) => Math.sin(t) ** 2 / 4, 4001, 'cosine'));
    expect(cosine.mean * 4).toBeCloseTo(0.5, 6);
    const uniform = errorStats(samplesOf((t) => Math.sin(t) ** 4 / 4, 4001, 'uniform'));
    expect(uniform.mean * 4).toBeCloseTo(3 / 8, 6);
    const cosine4 = errorStats(samplesOf((t) => Math.sin(t) ** 4 / 4, 4001, 'cosine'));
    expect(cosine4.mean * 4).toBeCloseTo(1 / 3, 6);
  });
  it('the angle of the max is where the error peaks', () => {
    const s = errorStats(samplesOf((t) => 0.1 * Math.exp(-(((t - 1) / 0.1) ** 2)), 1001, 'uniform'));
    expect(s.thetaAtMax).toBeCloseTo(1, 2);
    expect(s.max).toBeCloseTo(0.1, 5);
  });
  it('NaN and Infinity count, make max infinite and stay out of mean and rms; out-of-range values count', () => {
    const s = errorStats([
      { value: 0.2, reference: 0.1, theta: 0.1 },
      { value: NaN, reference: 0.1, theta: 0.2 },
      { value: Infinity, reference: 0.1, theta: 0.3 },
      { value: 1.25, reference: 1, theta: 0.4 },
      { value: -0.05, reference: 0, theta: 0.5 },
    ]);
    expect(s.nanCount).toBe(2);
    expect(s.max).toBe(Infinity);
    expect(s.thetaAtMax).toBe(0.2);
    expect(s.outOfRange).toBe(2);
    expect(s.mean).toBeCloseTo((0.1 + 0.25 + 0.05) / 3, 15);
    expect(s.rms).toBeCloseTo(Math.sqrt((0.01 + 0.0625 + 0.0025) / 3), 15);
  });
  it('a custom metric is used for every statistic; no samples give NaN mean', () => {
    const s = errorStats([{ value: 0.3, reference: 0.1, theta: 0 }], { metric: (v, r) => (v - r) / r });
    expect(s.max).toBeCloseTo(2, 12);
    const empty = createAccumulator().result();
    expect(empty.count).toBe(0);
    expect(empty.mean).toBeNaN();
    expect(absoluteError(0.25, 0.5)).toBe(0.25);
  });
});

describe('θ sampling and sweeps', () => {
  it('grids include 0 and 90° with cos 90° exactly 0, and weights sum to 1', () => {
    for (const weighting of ['uniform', 'cosine']) {
      const { theta, cos, weight } = thetaSamples(181, weighting);
      expect(theta[0]).toBe(0);
      expect(theta[180]).toBe(HALF_PI);
      expect(cos[180]).toBe(0);
      expect(cos[0]).toBe(1);
      expect(weight.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 14);
    }
    expect(thetaSamples(181, 'cosine').weight[0]).toBe(0); // sin 0 = 0
    expect(cosTheta(HALF_PI)).toBe(0);
    expect(() => thetaSamples(1)).toThrow(RangeError);
    expect(() => thetaSamples(10, 'beckmann')).toThrow(RangeError);
  });
  it('linspace includes both ends exactly', () => {
    const xs = linspace(1.3, 1.7, 5);
    expect(xs[0]).toBe(1.3);
    expect(xs[4]).toBe(1.7);
    [1.3, 1.4, 1.5, 1.6, 1.7].forEach((x, i) => expect(xs[i]).toBeCloseTo(x, 15));
    expect(linspace(0.4, 2.5, 106)[105]).toBe(2.5);
    expect(linspace(2, 3, 1)).toEqual([2]);
  });
  it('sweepDomain finds the worst case and angle over several cases and reports extra metrics', () => {
    const s = sweepDomain({
      evaluate: (c, a) => c * a,
      reference: (c) => c,
      cases: [[1.01], [1.03], [1.02]],
      thetaCount: 91,
      weighting: 'cosine',
      also: { relative: (v, r) => (r === 0 ? 0 : Math.abs(v - r) / r) },
    });
    expect(s.max).toBeCloseTo(0.03, 14);
    expect(s.thetaAtMax).toBe(0);
    expect(s.caseAtMax).toEqual([1.03]);
    expect(s.count).toBe(273);
    expect(s.also.relative.max).toBeCloseTo(0.03, 12);
    expect(s.also.relative.mean).toBeCloseTo(0.02, 12);
  });
});
