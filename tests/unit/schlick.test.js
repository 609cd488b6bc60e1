import { describe, expect, it } from 'vitest';
import { comparisonAngles, schlickComparison } from '../../src/panels/schlick/physics.js';
import { refinedMax } from '../../src/optics/refinedMax.js';
import { fresnelExact, fresnelSchlick, fresnelSchlickTIR } from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;

describe('schlickComparison', () => {
  it('air to glass: max error 0.0357 near 85°, the same for both variants', () => {
    const r = schlickComparison(1, 1.5);
    expect(r.worst.value).toBeCloseTo(0.0357, 4);
    expect(r.worst.theta).toBeGreaterThan(84);
    expect(r.worst.theta).toBeLessThan(86);
    expect(r.worstT).toEqual(r.worst);
    expect(r.critical).toBeNull();
    expect(r.schlickT).toEqual(r.schlick);
  });
  it('glass to air: Schlick is off by 0.959 at the critical angle 41.81°; on cos θt by 0.036', () => {
    const r = schlickComparison(1.5, 1);
    expect(r.critical).toBeCloseTo(41.8103, 4);
    expect(r.worst.value).toBeCloseTo(0.959, 3);
    expect(r.worst.theta).toBeCloseTo(41.8103, 4);
    expect(r.worstT.value).toBeCloseTo(0.0357, 4);
    expect(r.worstT.theta).toBeLessThan(r.critical);
    expect(r.worstT.theta).toBeGreaterThan(41);
  });
  it('water to air: 0.975 and 0.059', () => {
    const r = schlickComparison(1.333, 1);
    expect(r.worst.value).toBeCloseTo(0.975, 3);
    expect(r.worstT.value).toBeCloseTo(0.0592, 3);
  });
  it('the curves come from fresnel.js at every sampled angle', () => {
    const r = schlickComparison(1.5, 1, 91);
    r.theta.forEach((t, i) => {
      const c = t === 90 ? 0 : Math.cos(t * DEG);
      expect(r.exact[i]).toBe(fresnelExact(c, 1.5, 1));
      expect(r.schlick[i]).toBe(fresnelSchlick(c, 1.5, 1));
      expect(r.schlickT[i]).toBe(fresnelSchlickTIR(c, 1.5, 1));
      expect(r.error[i]).toBe(Math.abs(r.exact[i] - r.schlick[i]));
      expect(r.errorT[i]).toBe(Math.abs(r.exact[i] - r.schlickT[i]));
    });
  });
  it('angles are sorted, unique, span 0° to 90°, and add the θt grid only from the denser side', () => {
    const out = comparisonAngles(1.5, 1, 91);
    expect(out[0]).toBe(0);
    expect(out.at(-1)).toBe(90);
    for (let i = 1; i < out.length; i += 1) expect(out[i]).toBeGreaterThan(out[i - 1]);
    expect(out.filter((t) => t > 41 && t < 41.82).length).toBeGreaterThan(8); // an even grid alone: 1
    expect(comparisonAngles(1, 1.5, 91).length).toBe(92); // the grid plus Brewster
  });
  it('a grid maximum is refined, and stands where refining finds nothing larger', () => {
    expect(refinedMax([0, 1, 2, 3], [0.1, 0.5, 0.5, 0.2], () => 0)).toEqual({ value: 0.5, theta: 1 });
    const peak = refinedMax([0, 1, 2, 3], [0, 0.9, 0.8, 0], (t) => 1 - (t - 1.3) ** 2);
    expect(peak.theta).toBeCloseTo(1.3, 6); // a smooth maximum is flat: its place is good to about √ε
    expect(peak.value).toBeCloseTo(1, 12);
  });
});
