import { describe, expect, it } from 'vitest';
import {
  SPEED_OF_LIGHT_KM_S, evanescentDepth, fieldAt, isTotalInternalReflection, mediumWave, reflectionAmplitudeS,
  transmissionAmplitudeS, transmittedAngle, waveField,
} from '../../src/optics/waves.js';
import { criticalAngle, fresnelPolarized, fresnelTransmittance, snellCosT } from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;
const abs2 = (z) => z.re * z.re + z.im * z.im;

describe('wavelength and speed in a medium', () => {
  it('are λ0/n and c/n', () => {
    const glass = mediumWave(1.5, 550);
    expect(glass.wavelength).toBeCloseTo(366.6667, 4);
    expect(glass.speed).toBeCloseTo(2 / 3, 15);
    expect(glass.speedKmS).toBeCloseTo(199_861.639, 3);
    expect(mediumWave(1).speedKmS).toBe(SPEED_OF_LIGHT_KM_S);
  });
  it('rejects a non-positive index', () => {
    expect(() => mediumWave(0)).toThrow(RangeError);
  });
});

describe("Snell's law", () => {
  it('bends 30° from air into glass to 19.47°', () => {
    expect(transmittedAngle(30 * DEG, 1, 1.5) / DEG).toBeCloseTo(19.4712, 4);
    expect(isTotalInternalReflection(30 * DEG, 1, 1.5)).toBe(false);
  });
  it('n1 sin θ1 = n2 sin θ2 across angles and both directions', () => {
    for (const [n1, n2] of [[1, 1.5], [1.5, 1], [1, 1.333], [1.333, 2.417]]) {
      for (let d = 0; d <= 90; d += 2.5) {
        const t2 = transmittedAngle(d * DEG, n1, n2);
        if (t2 === null) continue;
        expect(n2 * Math.sin(t2)).toBeCloseTo(n1 * Math.sin(d * DEG), 13);
        expect(Math.cos(t2)).toBeCloseTo(snellCosT(Math.cos(d * DEG), n1, n2), 13);
      }
    }
  });
  it('has total internal reflection from glass to air past 41.81°, and none from air', () => {
    expect(criticalAngle(1.5, 1) / DEG).toBeCloseTo(41.8103, 4);
    expect(isTotalInternalReflection(60 * DEG, 1.5, 1)).toBe(true);
    expect(transmittedAngle(60 * DEG, 1.5, 1)).toBeNull();
    expect(isTotalInternalReflection(41.8 * DEG, 1.5, 1)).toBe(false);
    expect(isTotalInternalReflection(89.9 * DEG, 1, 3)).toBe(false);
  });
  it('rejects angles outside [0°, 90°]', () => {
    expect(() => transmittedAngle(-0.1, 1, 1.5)).toThrow(RangeError);
    expect(() => transmittedAngle(2, 1, 1.5)).toThrow(RangeError);
  });
});

describe('s-polarized field amplitudes', () => {
  it('|r_s|² is Rs, with a half-wave flip into the denser medium only', () => {
    for (const [n1, n2] of [[1, 1.5], [1.5, 1]]) {
      for (const d of [0, 20, 40]) {
        const r = reflectionAmplitudeS(d * DEG, n1, n2);
        expect(abs2(r)).toBeCloseTo(fresnelPolarized(Math.cos(d * DEG), n1, n2).s, 14);
        expect(Math.sign(r.re)).toBe(n1 < n2 ? -1 : 1);
        expect(r.im).toBe(0);
      }
    }
    expect(reflectionAmplitudeS(0, 1, 1.5).re).toBeCloseTo(-0.2, 15);
  });
  it('the transmitted field carries Ts = (n2 cosθ2)/(n1 cosθ1)·|t_s|²', () => {
    for (const [n1, n2] of [[1, 1.5], [1.5, 1], [1, 2.417]]) {
      for (const d of [0, 15, 30, 40, 60, 80]) {
        const theta = d * DEG;
        const t2 = transmittedAngle(theta, n1, n2);
        if (t2 === null) continue;
        const t = transmissionAmplitudeS(theta, n1, n2);
        const ts = ((n2 * Math.cos(t2)) / (n1 * Math.cos(theta))) * abs2(t);
        expect(ts).toBeCloseTo(fresnelTransmittance(Math.cos(theta), n1, n2).s, 12);
      }
    }
  });
  it('under total internal reflection |r_s| = 1 with the phase −2 atan(b/a)', () => {
    const r = reflectionAmplitudeS(60 * DEG, 1.5, 1);
    expect(abs2(r)).toBeCloseTo(1, 15);
    const a = 1.5 * Math.cos(60 * DEG);
    const b = Math.sqrt((1.5 * Math.sin(60 * DEG)) ** 2 - 1);
    expect(Math.atan2(r.im, r.re)).toBeCloseTo(-2 * Math.atan(b / a), 14);
    // (a − ib)/(a + ib) directly
    const den = a * a + b * b;
    expect(r.re).toBeCloseTo((a * a - b * b) / den, 14);
    expect(r.im).toBeCloseTo((-2 * a * b) / den, 14);
  });
  it('the reflected phase is continuous at the critical angle (0 just inside, 0 just past)', () => {
    const c = criticalAngle(1.5, 1);
    const inside = reflectionAmplitudeS(c - 1e-9, 1.5, 1);
    const past = reflectionAmplitudeS(c + 1e-9, 1.5, 1);
    expect(inside.re).toBeCloseTo(1, 3);
    expect(past.re).toBeCloseTo(1, 3);
  });
});

describe('evanescent field and wave vectors', () => {
  it('decays as exp(−κ|y|) with 1/κ = λ0 / (2π√(n1² sin²θ1 − n2²))', () => {
    const depth = evanescentDepth(60 * DEG, 1.5, 1, 550);
    expect(depth).toBeCloseTo(550 / (2 * Math.PI * Math.sqrt(1.6875 - 1)), 10);
    expect(evanescentDepth(30 * DEG, 1, 1.5)).toBeNull();
  });
  it('keeps the wave-vector component along the interface in both media (phase matching)', () => {
    const w = waveField(30 * DEG, 1, 1.5);
    expect(w.tir).toBe(false);
    expect(w.kx).toBeCloseTo(2 * Math.PI * 0.5, 14);
    // |k| = 2πn in each medium.
    expect(Math.hypot(w.kx, w.k1y)).toBeCloseTo(2 * Math.PI, 13);
    expect(Math.hypot(w.kx, w.k2y)).toBeCloseTo(2 * Math.PI * 1.5, 13);
    expect(w.kappa).toBe(0);
    const tir = waveField(60 * DEG, 1.5, 1);
    expect(tir.tir).toBe(true);
    expect(tir.theta2).toBeNull();
    expect(tir.kx ** 2 - tir.kappa ** 2).toBeCloseTo((2 * Math.PI) ** 2, 10); // kx² − κ² = k2²
  });
});

describe('the drawn field', () => {
  it('is continuous across the interface with the reflected wave (t = 1 + r), TIR too', () => {
    for (const [d, n1, n2] of [[30, 1, 1.5], [10, 1.5, 1], [60, 1.5, 1], [80, 1, 2.417], [0, 1, 1.333]]) {
      const w = waveField(d * DEG, n1, n2);
      for (const x of [-2, -0.37, 0, 0.8, 3.1]) {
        for (const phase of [0, 1, 4]) {
          const above = fieldAt(w, x, 0, phase, true);
          const below = fieldAt(w, x, -1e-12, phase, true);
          expect(below).toBeCloseTo(above, 9);
        }
      }
    }
  });
  it('has crests λ/n apart along the direction of travel in each medium', () => {
    const w = waveField(30 * DEG, 1, 1.5);
    const dirT = [Math.sin(w.theta2), -Math.cos(w.theta2)];
    const step = 1 / 1.5;
    const start = [0.3, -0.5];
    const f0 = fieldAt(w, start[0], start[1], 0.7);
    const f1 = fieldAt(w, start[0] + step * dirT[0], start[1] + step * dirT[1], 0.7);
    expect(f1).toBeCloseTo(f0, 12);
    const half = fieldAt(w, start[0] + 0.5 * step * dirT[0], start[1] + 0.5 * step * dirT[1], 0.7);
    expect(half).toBeCloseTo(-f0, 12);
  });
  it('decays below the interface under total internal reflection', () => {
    const w = waveField(60 * DEG, 1.5, 1);
    const depth = evanescentDepth(60 * DEG, 1.5, 1);
    const peak = Math.hypot(w.t.re, w.t.im);
    let max = 0;
    for (let x = 0; x < 2; x += 0.01) max = Math.max(max, Math.abs(fieldAt(w, x, -depth, 0)));
    expect(max).toBeCloseTo(peak / Math.E, 3);
  });
});
