import { describe, expect, it } from 'vitest';
import { fresnelLiteral, fresnelTerms, gSquared } from '../../src/panels/exact-fresnel/physics.js';
import { criticalAngle, fresnelExact, fresnelPolarized, snellCosT } from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;
const cosDeg = (d) => Math.cos(d * DEG);
const angles = Array.from({ length: 901 }, (_, i) => i / 10);
const pairs = [[1, 1.5], [1.5, 1], [1, 1.333], [1.333, 1], [1, 2.417], [2.417, 1], [1.31, 1.333], [1.333, 1.31]];

describe('fresnelTerms', () => {
  it('R equals fresnelExact to 1e-14 away from total internal reflection', () => {
    for (const [a, b] of pairs) {
      const critical = criticalAngle(a, b);
      for (const t of angles) {
        if (critical !== null && Math.abs(t * DEG - critical) < 0.01 * DEG) continue;
        const terms = fresnelTerms(cosDeg(t), a, b);
        expect(Math.abs(terms.R - fresnelExact(cosDeg(t), a, b)), `${a}→${b} at ${t}°`).toBeLessThan(1e-14);
      }
    }
  });
  it('R is ½ · first factor · second factor, and g is cos θt', () => {
    for (const [a, b] of pairs) {
      for (const t of [0, 10, 30, 40, 60, 85]) {
        const x = fresnelTerms(cosDeg(t), a, b);
        if (x.tir) continue;
        expect(x.R).toBeCloseTo(0.5 * x.factor1 * x.factor2, 15);
        expect(x.factor1).toBe(x.a * x.a);
        expect(x.factor2).toBe(1 + x.b * x.b);
        expect(x.g).toBeCloseTo(snellCosT(cosDeg(t), a, b), 15);
      }
    }
  });
  it('the lecture values at 60°, air to glass', () => {
    const x = fresnelTerms(cosDeg(60), 1, 1.5);
    expect(x.m).toBeCloseTo(2 / 3, 15);
    expect(x.c).toBeCloseTo(1 / 3, 15);
    expect(x.g2).toBeCloseTo(2 / 3, 15); // (1 − 4/9) + 1/9
    expect(x.R).toBeCloseTo(0.0891867, 7);
    const { s, p } = fresnelPolarized(cosDeg(60), 1, 1.5);
    expect(x.R).toBeCloseTo(0.5 * (s + p), 14);
    expect(x.tir).toBe(false);
  });
  it('past the critical angle g² < 0, g is imaginary (NaN) and R = 1', () => {
    const x = fresnelTerms(cosDeg(50), 1.5, 1);
    expect(x.tir).toBe(true);
    expect(x.g2).toBeCloseTo((1 - 1.5) * (1 + 1.5) + (1.5 * cosDeg(50)) ** 2, 14);
    expect(x.g2).toBeLessThan(0);
    expect(x.g).toBeNaN();
    expect(x.R).toBe(1);
    expect(fresnelExact(cosDeg(50), 1.5, 1)).toBe(1);
  });
  it('the TIR test agrees with fresnel.js right at the critical angle', () => {
    for (const [a, b] of pairs.filter(([a, b]) => a > b)) {
      const critical = criticalAngle(a, b);
      for (const d of [-1e-9, 0, 1e-9]) {
        const ci = Math.cos(critical + d);
        expect(fresnelTerms(ci, a, b).tir).toBe(snellCosT(ci, a, b) === null || gSquared(ci, a, b) === 0);
        expect(fresnelTerms(ci, a, b).R).toBeCloseTo(fresnelExact(ci, a, b), 12);
      }
    }
  });
  it('matched indices reflect nothing, grazing included', () => {
    for (const ci of [1, 0.5, 1e-9, Math.cos(Math.PI / 2), 0]) expect(fresnelTerms(ci, 1.4, 1.4).R).toBe(0);
    expect(gSquared(0.3, 1.4, 1.4)).toBeCloseTo(0.09, 16);
  });
});

describe('fresnelLiteral: the order of g² matters', () => {
  it('agrees with fresnelExact for ordinary inputs, in both orders', () => {
    for (const [a, b] of [[1, 1.5], [1, 1.333], [1.5, 1]]) {
      for (const t of [0, 30, 60, 80]) {
        for (const order of ['lecture', 'safe']) {
          expect(fresnelLiteral(cosDeg(t), a, b, order).R).toBeCloseTo(fresnelExact(cosDeg(t), a, b), 12);
        }
      }
    }
  });
  it('with m = 1 and c below about 1e-8 the lecture order gives R = 1, the safe order 0', () => {
    for (const c of [1e-8, 1e-12, Math.cos(Math.PI / 2)]) {
      const lecture = fresnelLiteral(c, 1.2, 1.2, 'lecture');
      expect(lecture.g2).toBe(0);
      expect(lecture.R).toBe(1);
      const safe = fresnelLiteral(c, 1.2, 1.2, 'safe');
      expect(safe.g2).toBeGreaterThan(0);
      expect(safe.R).toBeLessThan(1e-15);
    }
    // Above the threshold both orders see c² and agree.
    expect(fresnelLiteral(1e-6, 1.2, 1.2, 'lecture').R).toBeLessThan(1e-8);
  });
  it('takes the total-internal-reflection branch for g² < 0', () => {
    expect(fresnelLiteral(cosDeg(50), 1.5, 1, 'lecture')).toMatchObject({ R: 1 });
    expect(fresnelLiteral(cosDeg(50), 1.5, 1, 'safe').g2).toBeLessThan(0);
  });
});
