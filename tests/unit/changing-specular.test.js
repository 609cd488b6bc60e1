import { describe, expect, it } from 'vitest';
import { fresnelExact, normalIncidence } from '../../src/optics/fresnel.js';
import {
  peakHighlightCurves, phongConstant, phongFresnel, phongGeometry, phongHighlights, phongSpecular,
} from '../../src/optics/phong.js';

const DEG = Math.PI / 180;

describe('Phong lobe', () => {
  it('is (v·r)^s, clamped to 0 behind and 1 at the mirror direction', () => {
    expect(phongSpecular(1, 60)).toBe(1);
    expect(phongSpecular(0.9, 2)).toBeCloseTo(0.81, 15);
    expect(phongSpecular(-0.5, 3)).toBe(0);
    expect(() => phongSpecular(Number.NaN, 3)).toThrow(RangeError);
  });
  it('plain Phong is R0 times the lobe; Phong × F is F(θ) times it', () => {
    expect(phongConstant(0.95, 20, 1, 1.5)).toBeCloseTo(0.04 * 0.95 ** 20, 15);
    const c = Math.cos(70 * DEG);
    expect(phongFresnel(0.95, 20, c, 1, 1.5)).toBeCloseTo(fresnelExact(c, 1, 1.5) * 0.95 ** 20, 15);
  });
});

describe('cross-section geometry', () => {
  it('the view in the mirror direction has v·r = 1 and θ = 90° − elevation', () => {
    const g = phongGeometry(25, 25);
    expect(g.vDotR).toBe(1);
    expect(g.thetaDeg).toBe(65);
    expect(g.cosThetaI).toBeCloseTo(Math.cos(65 * DEG), 15);
  });
  it('v·r is the cosine of the angle between view and mirror elevations', () => {
    expect(phongGeometry(30, 50).vDotR).toBeCloseTo(Math.cos(20 * DEG), 15);
    const h = phongHighlights(30, 50, 10, 1, 1.5);
    expect(h.phongF / h.phong).toBeCloseTo(h.F / h.R0, 12);
  });
});

describe('peak highlight against elevation', () => {
  const curves = peakHighlightCurves(1, 1.5);
  const at = (name, e) => curves[name][curves.elevation.indexOf(e)];
  it('runs from 0° to 90° with 5° and 80° on the grid', () => {
    expect(curves.elevation[0]).toBe(0);
    expect(curves.elevation.at(-1)).toBe(90);
    expect(curves.elevation).toContain(5);
    expect(curves.elevation).toContain(80);
  });
  it('plain Phong is R0 at every elevation', () => {
    expect(new Set(curves.phong)).toEqual(new Set([normalIncidence(1, 1.5)]));
    expect(at('phong', 5)).toBe(at('phong', 80));
  });
  it('Phong × F rises towards grazing: R0 overhead, 1 at 0°, more at 5° than at 80°', () => {
    expect(at('phongF', 90)).toBeCloseTo(0.04, 15);
    expect(at('phongF', 0)).toBe(1);
    expect(at('phongF', 5)).toBeGreaterThan(10 * at('phongF', 80));
    for (let i = 1; i < curves.elevation.length; i += 1) expect(curves.phongF[i]).toBeLessThanOrEqual(curves.phongF[i - 1]);
  });
  it('the index changes the F curve', () => {
    const other = peakHighlightCurves(1, 2.4);
    expect(other.phongF[10]).not.toBeCloseTo(curves.phongF[10], 3);
    expect(other.phong[0]).toBeCloseTo(((2.4 - 1) / 3.4) ** 2, 15);
  });
});
