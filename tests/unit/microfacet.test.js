import { describe, expect, it } from 'vitest';
import { ggxDistribution, microfacetSpecular, smithG2, smithLambda } from '../../src/optics/microfacet.js';

const DEG = Math.PI / 180;

describe('GGX distribution', () => {
  it('is normalized: the projected microfacet area ∫ D(h) cosθh dω is 1', () => {
    for (const alpha of [0.1, 0.3, 0.64, 1]) {
      // Midpoint rule in θ over the hemisphere, dω = 2π sinθ dθ (D is isotropic).
      const steps = 200000;
      let sum = 0;
      for (let i = 0; i < steps; i += 1) {
        const t = ((i + 0.5) / steps) * (Math.PI / 2);
        sum += ggxDistribution(Math.cos(t), alpha) * Math.cos(t) * 2 * Math.PI * Math.sin(t);
      }
      expect(sum * (Math.PI / 2 / steps)).toBeCloseTo(1, 5);
    }
  });
  it('peaks at 1/(πα²) along the normal and is 1/π everywhere for α = 1', () => {
    expect(ggxDistribution(1, 0.5)).toBeCloseTo(1 / (Math.PI * 0.25), 14);
    for (const c of [0, 0.3, 0.9]) expect(ggxDistribution(c, 1)).toBeCloseTo(1 / Math.PI, 14);
  });
  it('rejects a bad alpha instead of returning NaN', () => {
    expect(() => ggxDistribution(1, 0)).toThrow(RangeError);
    expect(() => ggxDistribution(1, Number.NaN)).toThrow(RangeError);
  });
});

describe('Smith masking-shadowing', () => {
  it('Λ matches its tan form (−1 + √(1 + α² tan²θ))/2', () => {
    for (const theta of [5, 30, 60, 85, 89]) {
      const tan = Math.tan(theta * DEG);
      expect(smithLambda(Math.cos(theta * DEG), 0.4)).toBeCloseTo((-1 + Math.sqrt(1 + 0.16 * tan * tan)) / 2, 12);
    }
  });
  it('is 1 head-on, falls towards grazing and is 0 at grazing', () => {
    expect(smithG2(1, 1, 0.64)).toBe(1);
    expect(smithG2(Math.cos(60 * DEG), Math.cos(80 * DEG), 0.64)).toBeLessThan(smithG2(Math.cos(30 * DEG), 1, 0.64));
    expect(smithG2(0, 1, 0.64)).toBe(0);
  });
});

describe('Cook–Torrance specular', () => {
  it('is D·G·F / (4 cosθl cosθv) and 0 below the surface', () => {
    const args = { cosL: 0.2, cosV: 0.1, cosH: 0.99, alpha: 0.5, F: 0.3 };
    const expected = (ggxDistribution(0.99, 0.5) * smithG2(0.2, 0.1, 0.5) * 0.3) / (4 * 0.2 * 0.1);
    expect(microfacetSpecular(args)).toBeCloseTo(expected, 14);
    expect(microfacetSpecular({ ...args, cosV: 0 })).toBe(0);
    expect(microfacetSpecular({ ...args, cosL: -0.1 })).toBe(0);
  });
});
