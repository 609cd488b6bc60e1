import { describe, expect, it } from 'vitest';
import { metalCurves, metalCurveStats, schlickForF0, schlickIndexForF0 } from '../../src/panels/metals/physics.js';
import { metalById } from '../../src/optics/materials.js';
import { absError, conductorR, cosOfDegrees } from './oracle/fresnelOracle.js';

const DEG = Math.PI / 180;

describe('Schlick with a given F0', () => {
  it('is F0 head-on, 1 at grazing, and the slide polynomial between', () => {
    for (const f0 of [0, 0.04, 0.408, 0.956, 0.99]) {
      expect(schlickForF0(1, f0)).toBeCloseTo(f0, 13);
      expect(schlickForF0(0, f0)).toBe(1);
      const c = Math.cos(60 * DEG);
      expect(schlickForF0(c, f0)).toBeCloseTo(f0 + (1 - f0) * (1 - c) ** 5, 13);
    }
  });
  it('maps F0 to the dielectric index with that R0, and rejects bad F0', () => {
    expect(schlickIndexForF0(0.04)).toBeCloseTo(1.5, 12);
    expect(schlickIndexForF0(0)).toBe(1);
    expect(schlickIndexForF0(1)).toBeNull();
    expect(schlickForF0(0.3, 1)).toBe(1);
    expect(() => schlickIndexForF0(1.2)).toThrow(RangeError);
    expect(() => schlickIndexForF0(Number.NaN)).toThrow(RangeError);
  });
});

describe('metal curves', () => {
  const gold = metalById('gold');
  const aluminium = metalById('aluminium');

  it('start at F0 per channel (gold ≈ 0.956, 0.792, 0.408) and reach 1 at 90°', () => {
    const curves = metalCurves(gold);
    expect(curves.theta).toHaveLength(361);
    [0.956, 0.792, 0.408].forEach((v, ch) => {
      expect(absError(curves.f0[ch], conductorR(1, gold.n[ch], gold.k[ch]))).toBeLessThan(1e-12); // the 50-digit oracle
      expect(curves.f0[ch]).toBeCloseTo(v, 3);
      expect(curves.exact[ch][0]).toBeCloseTo(curves.f0[ch], 12);
      expect(curves.schlick[ch][0]).toBeCloseTo(curves.f0[ch], 12);
      expect(curves.exact[ch].at(-1)).toBe(1);
      expect(curves.schlick[ch].at(-1)).toBe(1);
    });
  });

  it('sample the exact conductor Fresnel of each channel', () => {
    const curves = metalCurves(aluminium, 91);
    expect(curves.theta[60]).toBe(60);
    for (let ch = 0; ch < 3; ch += 1) {
      expect(absError(curves.exact[ch][60], conductorR(cosOfDegrees(60), aluminium.n[ch], aluminium.k[ch]))).toBeLessThan(1e-12); // the 50-digit oracle
      expect(curves.error[ch][60]).toBe(Math.abs(curves.exact[ch][60] - curves.schlick[ch][60]));
    }
  });

  it("aluminium's red channel dips below F0 near 80°, where Schlick errs most", () => {
    const [red, green, blue] = metalCurveStats(metalCurves(aluminium), aluminium);
    expect(red.f0).toBeCloseTo(0.9056, 4);
    expect(red.minimum.theta).toBeGreaterThan(78);
    expect(red.minimum.theta).toBeLessThan(86);
    expect(red.dip).toBeGreaterThan(0.05);
    expect(red.maxError.value).toBeGreaterThan(0.1);
    expect(red.maxError.theta).toBeGreaterThan(80);
    for (const stat of [green, blue]) expect(stat.dip).toBeGreaterThan(0.02);
  });

  it('report no dip where the exact curve never falls below F0 (a dielectric-like channel)', () => {
    const dielectric = { n: [1.5, 1.5, 1.5], k: [0, 0, 0] };
    const [stat] = metalCurveStats(metalCurves(dielectric), dielectric);
    expect(stat.dip).toBe(0);
    expect(stat.minimum.theta).toBe(0);
    expect(stat.f0).toBeCloseTo(0.04, 12);
    expect(stat.maxError.theta).toBeGreaterThan(80); // dielectric Schlick errs most near 85°
  });
});

describe('where the lecture\'s "almost no Fresnel factor" falls short', async () => {
  const { metalsLectureGap, NEUTRAL } = await import('../../src/panels/metals/words.js');
  const { channelsAt } = await import('../../src/panels/metals/physics.js');
  const { metals } = await import('../../src/optics/materials.js');
  const { fresnelConductorPolarized } = await import('../../src/optics/fresnel.js');
  const stats = (m) => metalCurveStats(metalCurves(m), m);
  it('gold: from 0.96, 0.79, 0.41 head-on to 0.99, 0.98, 0.94 at 89°, its tint fading', () => {
    const gold = metalById('gold');
    const text = metalsLectureGap(gold, stats(gold));
    const [head, grazing] = [channelsAt(gold, 0), channelsAt(gold, 89)];
    expect(head.map((x) => x.toFixed(2))).toEqual(['0.96', '0.79', '0.41']);
    expect(grazing.map((x) => x.toFixed(2))).toEqual(['0.99', '0.98', '0.94']);
    expect(text).toContain('0.96, 0.79, 0.41 at 0°, 0.99, 0.98, 0.94 at 89°');
    expect(text).toContain('tint fades towards white');
    expect(text).toContain('first dips below F0 in red and green (by up to 0.007, red, near 70°)');
    expect(text).toContain('Head-on its F0 carries its colour');
    // Copper's blue dips by 1.2e−5 only: not named. A neutral metal's colour is not claimed.
    const copper = metalById('copper');
    expect(stats(copper)[2].dip).toBeGreaterThan(0);
    expect(stats(copper)[2].dip).toBeLessThan(0.001);
    expect(metalsLectureGap(copper, stats(copper))).toContain('dips below F0 in red and green (by up to 0.010, red, near 70°; blue by under 0.001)');
    expect(metalsLectureGap(metalById('iron'), stats(metalById('iron')))).toContain('Head-on it reflects every channel nearly alike');
  });
  it('iron: green and blue fall to about 0.49 near 65–70°; silver, aluminium and iron are nearly neutral', () => {
    const iron = stats(metalById('iron'));
    expect(iron[1].minimum.value).toBeCloseTo(0.49, 2);
    expect(iron[2].minimum.value).toBeCloseTo(0.49, 1);
    for (const s of iron.slice(1)) expect(s.minimum.theta > 63 && s.minimum.theta < 70).toBe(true);
    for (const id of ['silver', 'aluminium', 'iron']) {
      const m = metalById(id);
      expect(Math.max(...channelsAt(m, 0)) - Math.min(...channelsAt(m, 0))).toBeLessThan(NEUTRAL);
    }
    // Neutral at every angle only where it is: iron. Aluminium's channels part near 85° (blue above red).
    const spreadAt = (m, t) => Math.max(...channelsAt(m, t)) - Math.min(...channelsAt(m, t));
    const iron2 = metalById('iron');
    for (let t = 0; t <= 89; t += 0.5) expect(spreadAt(iron2, t)).toBeLessThan(NEUTRAL);
    expect(metalsLectureGap(iron2, stats(iron2))).toContain('nearly neutral at every angle (its channels within 0.04 of each other)');
    const al = metalById('aluminium');
    expect(spreadAt(al, 85)).toBeGreaterThan(0.07);
    expect(channelsAt(al, 85)[2]).toBeGreaterThan(channelsAt(al, 85)[0]);
    expect(metalsLectureGap(al, stats(al))).toContain('but near 85° its channels are up to 0.07 apart, a faint cool cast');
    // Silver: the lecture's words hold, and the note says so.
    const silver = metalById('silver');
    for (let t = 0; t <= 89; t += 0.5) {
      channelsAt(silver, t).forEach((r, ch) => expect(Math.abs(r - channelsAt(silver, 0)[ch])).toBeLessThan(0.02));
    }
    expect(metalsLectureGap(silver, stats(silver))).toContain('for silver it is close: in every channel R stays within 0.018 of F0');
    for (const id of ['gold', 'copper']) expect(metalsLectureGap(metalById(id), stats(metalById(id))), id).toContain('tint fades');
  });
  it('every metal rises towards 1 at grazing in every channel, with a pseudo-Brewster angle where Rp is least', () => {
    for (const m of metals) {
      const grazing = channelsAt(m, 89.9);
      for (let ch = 0; ch < 3; ch += 1) expect(grazing[ch]).toBeGreaterThan(channelsAt(m, 0)[ch]);
      for (const [ch, s] of stats(m).entries()) {
        // No angle on a 0.02° grid has a smaller Rp than the refined pseudo-Brewster angle's.
        for (let t = 0; t <= 90; t += 0.02) {
          expect(fresnelConductorPolarized(Math.cos(t * DEG), m.n[ch], m.k[ch]).p)
            .toBeGreaterThanOrEqual(s.pseudoBrewster.rp - 1e-12);
        }
        expect(s.pseudoBrewster.theta > 60 && s.pseudoBrewster.theta < 85, `${m.id} ${ch}`).toBe(true);
        // The principal angle (p–s phase 90°) lies a little beyond it (Azzam, JOSA A 25, 2858, 2008).
        expect(s.principal.theta, `${m.id} ${ch}`).toBeGreaterThan(s.pseudoBrewster.theta);
        expect(s.principal.theta - s.pseudoBrewster.theta, `${m.id} ${ch}`).toBeLessThan(6);
      }
    }
  });
});

describe('the principal angle, where the p–s phase difference is 90°', async () => {
  const { conductorPhaseDifference, principalAngle } = await import('../../src/optics/conductorPhase.js');
  const { metals } = await import('../../src/optics/materials.js');
  const stats = (m) => metalCurveStats(metalCurves(m), m);
  // Independent of conductorPhase.js: the ellipsometric ratio rp/rs = (sin θ tan θ − w)/(sin θ tan θ + w),
  // w = √(η² − sin²θ) (Azzam & Bashara, Ellipsometry and Polarized Light, 1977, §4.3), in plain complex numbers.
  const ratio = (t, n, k) => {
    const th = t * DEG;
    const st = Math.sin(th) * Math.tan(th);
    const [x, y] = [n * n - k * k - Math.sin(th) ** 2, 2 * n * k];
    const r = Math.hypot(x, y);
    const w = [Math.sqrt((r + x) / 2), Math.sqrt((r - x) / 2)]; // y > 0: the root in the first quadrant
    const num = [st - w[0], -w[1]];
    const den = [st + w[0], w[1]];
    const q = den[0] ** 2 + den[1] ** 2;
    return [(num[0] * den[0] + num[1] * den[1]) / q, (num[1] * den[0] - num[0] * den[1]) / q];
  };
  const delta = (t, n, k) => Math.abs(Math.atan2(ratio(t, n, k)[1], ratio(t, n, k)[0])) / DEG;

  it('gold: 75.5°, 70.6° and 69.0° (red, green, blue), a few degrees past its Rp minima 73.5°, 65.9°, 65.1°', () => {
    const gold = metalById('gold');
    const s = stats(gold);
    expect(s.map((c) => c.principal.theta.toFixed(1))).toEqual(['75.5', '70.6', '69.0']);
    expect(s.map((c) => c.pseudoBrewster.theta.toFixed(1))).toEqual(['73.5', '65.9', '65.1']);
    for (const [ch, c] of s.entries()) expect(delta(c.principal.theta, gold.n[ch], gold.k[ch])).toBeCloseTo(90, 8);
  });
  it('agrees with the ellipsometric ratio at every angle, falling from 180° head-on to 0° at grazing', () => {
    for (const m of metals) {
      for (let ch = 0; ch < 3; ch += 1) {
        for (const t of [1, 20, 45, 60, 70, 75, 80, 85, 89]) {
          expect(conductorPhaseDifference(Math.cos(t * DEG), m.n[ch], m.k[ch])).toBeCloseTo(delta(t, m.n[ch], m.k[ch]), 9);
        }
        expect(conductorPhaseDifference(1, m.n[ch], m.k[ch])).toBeCloseTo(180, 9);
        expect(conductorPhaseDifference(0, m.n[ch], m.k[ch])).toBeCloseTo(0, 9);
      }
    }
    expect(principalAngle(1.5, 0)).toBeNull(); // a dielectric has Brewster's angle instead
  });
  it('falls monotonically for the lab\'s metals, so each channel has one principal angle', () => {
    for (const m of metals) {
      for (let ch = 0; ch < 3; ch += 1) {
        let previous = 181;
        for (let i = 0; i <= 9000; i += 1) {
          const d = delta(Math.max(i / 100, 1e-6), m.n[ch], m.k[ch]);
          expect(d, `${m.id} ${ch} at ${i / 100}°`).toBeLessThanOrEqual(previous + 1e-9);
          previous = d;
        }
      }
    }
  });
});
