import { describe, expect, it } from 'vitest';
import { interfaceSplit, interfaceSplitCurve } from '../../src/panels/angle-ratio/physics.js';
import { cosDeg } from '../../src/optics/angles.js';
import { fresnelExact } from '../../src/optics/fresnel.js';
import { absError, cosOfDegrees, dielectricR } from './oracle/fresnelOracle.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

const DEG = Math.PI / 180;

describe('interfaceSplit (angle-ratio panel)', () => {
  it('air to glass: R = 0.0400 head-on and 0.3877 at 80°, T = 1 − R', () => {
    const head = interfaceSplit(0, 1, 1.5);
    expect(head.R.toFixed(4)).toBe('0.0400');
    expect(head.T).toBeCloseTo(0.96, 12);
    expect(head.thetaT).toBe(0);
    const at80 = interfaceSplit(80, 1, 1.5);
    expect(absError(at80.R, dielectricR(cosOfDegrees(80), 1, 1.5))).toBeLessThan(1e-12); // the 50-digit oracle: 0.387704354691…
    expect(at80.R.toFixed(4)).toBe('0.3877');
    expect(at80.R + at80.T).toBe(1);
  });
  it('the refracted direction follows Snell’s law', () => {
    const s = interfaceSplit(45, 1, 1.5);
    expect(Math.sin(s.thetaT * DEG) * 1.5).toBeCloseTo(Math.sin(45 * DEG), 12);
    expect(s.tir).toBe(false);
    expect(s.critical).toBeNull();
  });
  it('glass to air: a refracted ray below the critical angle, none past it', () => {
    const critical = Math.asin(1 / 1.5) / DEG;
    const inside = interfaceSplit(41, 1.5, 1);
    expect(inside.tir).toBe(false);
    expect(inside.thetaT).toBeGreaterThan(79);
    expect(inside.T).toBeGreaterThan(0);
    const past = interfaceSplit(45, 1.5, 1);
    expect(past).toMatchObject({ tir: true, thetaT: null, R: 1, T: 0 });
    expect(past.critical).toBeCloseTo(critical, 12);
    expect(interfaceSplit(critical, 1.5, 1).T).toBe(0);
  });
  it('equal indices: nothing reflects, the ray goes straight on', () => {
    const s = interfaceSplit(30, 1.333, 1.333);
    expect(s.R).toBe(0);
    expect(s.T).toBe(1);
    expect(s.thetaT).toBeCloseTo(30, 10);
  });
  it('cos 90° is exactly 0 and grazing light is all reflected', () => {
    expect(cosDeg(90)).toBe(0);
    expect(interfaceSplit(90, 1, 1.5).R).toBe(1);
  });
  it('the CSV curve spans 0° to 90° with R + T = 1 and includes the critical angle', () => {
    const { theta, R, T } = interfaceSplitCurve(1.5, 1);
    expect(theta[0]).toBe(0);
    expect(theta.at(-1)).toBe(90);
    expect(theta).toContain(Math.asin(1 / 1.5) / DEG);
    R.forEach((r, i) => expect(r + T[i]).toBeCloseTo(1, 15));
    expect(R[0]).toBeCloseTo(0.04, 12);
    expect(R.at(-1)).toBe(1);
  });
});

describe('the stone-skipping analogy says how far it holds', async () => {
  const { stoneAnalogy } = await import('../../src/panels/angle-ratio/words.js');
  const { halfReflectedAngle } = await import('../../src/panels/angle-ratio/physics.js');
  it('from air into glass light mostly reflects only past 82.8°: R = 0.39 at 80°, 0.56 at 84°', () => {
    const half = halfReflectedAngle(1, 1.5);
    expect(fresnelExact(cosDeg(half), 1, 1.5)).toBeCloseTo(0.5, 12);
    expect(fresnelExact(cosDeg(half - 0.1), 1, 1.5)).toBeLessThan(0.5);
    const text = stoneAnalogy(1, 1.5);
    expect(text).toContain('only past 82.8° from the normal');
    expect(text).toContain(`R = ${fresnelExact(cosDeg(80), 1, 1.5).toFixed(2)} at 80°, ${fresnelExact(cosDeg(84), 1, 1.5).toFixed(2)} at 84°`);
    expect(text).toContain('R = 0.39 at 80°, 0.56 at 84°');
    expect(text).toContain('not a stone that bounces');
    expect(text).toContain('Its trend holds at every angle: R grows from 0.040 head-on to 1 at grazing');
    expect(text).toContain('Its slide says the greater the angle between the stone\'s velocity and the water\'s surface, the more it '
      + 'skips; it is the other way round');
    expect(stoneAnalogy(1.333, 1.5)).toContain('R grows from 0.0035 head-on'); // never 0.00
  });
  it('its trend holds at every angle: unpolarized R never falls as the incidence flattens, for ratios below 2 + √3', () => {
    // Checked on a 0.01° grid from head-on to grazing (or to the critical angle), both ways, for ratios from 1.1 to 3.7
    // (the panel offers up to 3); float64 rounding near 0° allows a change of 1e-15.
    for (const n of [1.1, 1.33, 1.5, 2, 2.42, 3, 3.7]) {
      for (const [nI, nT] of [[1, n], [n, 1]]) {
        let previous = -1;
        for (let i = 0; i <= 9000; i += 1) {
          const r = fresnelExact(cosDeg(i / 100), nI, nT);
          expect(r, `${nI} → ${nT} at ${i / 100}°`).toBeGreaterThanOrEqual(previous - 1e-15);
          previous = r;
        }
      }
    }
  });
  it('past a ratio of 2 + √3 R dips a little before it rises, which is why the comment names the bound', () => {
    let dips = false;
    for (let i = 1, previous = fresnelExact(1, 1, 4); i <= 9000; i += 1) {
      const r = fresnelExact(cosDeg(i / 100), 1, 4);
      if (r < previous - 1e-12) dips = true;
      previous = r;
    }
    expect(dips).toBe(true);
  });
  it('from the denser side it points to total internal reflection, far from grazing; equal indices reflect nothing', () => {
    expect(stoneAnalogy(1.5, 1)).toContain('critical angle, 41.8°, 48.2° short of grazing. A stone also skips only when');
    expect(stoneAnalogy(1.0001, 1)).toMatch(/passes 0\.5 at 89\.\d\d° and reaches 1 at the critical angle, 89\.\d\d°/);
    expect(stoneAnalogy(1.5, 1)).toContain('R also grows with the angle, from 0.040 head-on, but it passes 0.5 at 41.4° and reaches 1 at the critical angle');
    expect(halfReflectedAngle(1.5, 1.5)).toBeNull();
    expect(stoneAnalogy(1.5, 1.5)).toContain('nothing is reflected at any angle');
  });
});

describe('the stone-skipping analogy in another language', async () => {
  const { stoneAnalogy } = await import('../../src/panels/angle-ratio/words.js');
  usePseudoLocale();
  it('is one message of the catalogue in every case: into the denser side, out of it, equal indices, near grazing', () => {
    for (const [nI, nT] of [[1, 1.5], [1.5, 1], [1.5, 1.5], [1.0001, 1], [1, 1.0001]]) {
      const text = stoneAnalogy(nI, nT);
      expect(text.startsWith('⟦'), `${nI} → ${nT}`).toBe(true);
      expect(wordsOutside(text), `${nI} → ${nT}`).toBe('');
    }
  });
});
