import { describe, expect, it } from 'vitest';
import {
  alphaFromExponent, cleanAlpha, cleanVariance, exponentFromAlpha, leanAlpha, leanCovariance, reconstructZ,
  toksvigAlpha, toksvigExponent, toksvigFactor, toksvigVariance, vmfAlpha, vmfKappa, vmfMeanLength,
} from '../../src/normals/lobeFormulas.js';

const lerp = (a, b, t) => a + (b - a) * t;

describe('Toksvig (Toksvig 2004)', () => {
  it('σ² = (1 − L)/L, and L = 1/(1 + σ²)', () => {
    expect(toksvigVariance(Math.cos(Math.PI / 6))).toBeCloseTo(0.1547, 4);
    expect(toksvigVariance(Math.SQRT1_2)).toBeCloseTo(0.4142, 4);
    expect(toksvigVariance(1)).toBe(0);
    expect(toksvigVariance(1.002)).toBe(0); // 8-bit noise above 1
    expect(toksvigVariance(0)).toBe(Infinity);
    for (const v of [0.01, 0.3, 2]) expect(toksvigVariance(1 / (1 + v))).toBeCloseTo(v, 12);
  });

  it("the factor at |N| = 0.995: f_t ≈ 0.66 at s = 100 and ≈ 0.16 at s = 1000", () => {
    expect(toksvigFactor(0.995, 100)).toBeCloseTo(0.665552, 6);
    expect(toksvigFactor(0.995, 1000)).toBeCloseTo(0.165972, 6);
    expect(toksvigFactor(1, 1000)).toBe(1);
    // Hill's shader form: ft = len / lerp(s, 1, len)
    for (const [L, s] of [[0.9, 16], [0.995, 100], [0.5, 1000]]) expect(toksvigFactor(L, s)).toBeCloseTo(L / lerp(s, 1, L), 12);
    expect(toksvigExponent(0.995, 100)).toBeCloseTo(66.5552, 4);
  });

  it('GGX form at known points: α at L = 1, 1 at α = 1 or L → 0, 0.625507 for (cos 30°, 0.5)', () => {
    expect(toksvigAlpha(1, 0.3)).toBeCloseTo(0.3, 15);
    expect(toksvigAlpha(0.7, 1)).toBeCloseTo(1, 15);
    expect(toksvigAlpha(0, 0.2)).toBe(1);
    expect(toksvigAlpha(Math.cos(Math.PI / 6), 0.5)).toBeCloseTo(0.625507, 6);
    // small-variance limit α'² ≈ α² + 2σ²
    const L = 1 / (1 + 1e-4);
    expect(toksvigAlpha(L, 0.05) ** 2 / (0.05 ** 2 + 2e-4)).toBeCloseTo(1, 3);
  });

  it("equals MJP's route (s = 2/α² − 2, α′ = √(2/(f_t s + 2))) and Unreal's on a grid", () => {
    for (const alpha of [0.02, 0.1, 0.3, 0.6, 0.9]) {
      for (const L of [0.3, 0.8, 0.95, 0.999]) {
        const s = exponentFromAlpha(alpha);
        const mjp = Math.sqrt(2 / (toksvigFactor(L, s) * s + 2));
        const a2 = alpha * alpha;
        const B = 2 * toksvigVariance(L) * (a2 - 1);
        const unreal = Math.sqrt((B - a2) / (B - 1));
        expect(toksvigAlpha(L, alpha)).toBeCloseTo(mjp, 12);
        expect(toksvigAlpha(L, alpha)).toBeCloseTo(unreal, 12);
        // Blinn-Phong and GGX agree through s = 2/α² − 2
        expect(exponentFromAlpha(toksvigAlpha(L, alpha))).toBeCloseTo(toksvigExponent(L, s), 8);
      }
    }
  });

  it('s ↔ α mapping round-trips', () => {
    expect(exponentFromAlpha(0.2)).toBeCloseTo(48, 12);
    expect(alphaFromExponent(48)).toBeCloseTo(0.2, 15);
  });
});

describe('vMF (Han et al. 2007)', () => {
  it('κ from r̄: 10.37 for κ = 10 and 100.5 for κ = 100; 10000 at r̄ = 1', () => {
    expect(vmfMeanLength(10)).toBeCloseTo(0.9, 8);
    expect(vmfKappa(vmfMeanLength(10))).toBeCloseTo(10.374, 3);
    expect(vmfKappa(vmfMeanLength(100))).toBeCloseTo(100.487, 3);
    expect(vmfKappa(1)).toBe(10000);
    expect(vmfKappa(0)).toBe(0);
    // for large κ, 1 − r ≈ 1/κ ≈ Toksvig's σ²
    expect((1 - vmfMeanLength(1000)) * 1000).toBeCloseTo(1, 2);
  });

  it('α′ = √(α² + 2/κ)', () => {
    expect(vmfAlpha(1, 0.3)).toBeCloseTo(Math.sqrt(0.09 + 2e-4), 15);
    expect(vmfAlpha(Math.cos(Math.PI / 6), 0.5)).toBeCloseTo(0.711758, 6);
    expect(vmfAlpha(0, 0.5)).toBe(Infinity);
  });
});

describe('LEAN and CLEAN (Olano & Baker 2010, Baker 2011)', () => {
  it('no variance: Σ = α²/2 · I, α′ = α in every direction', () => {
    const c = leanCovariance(0.3, -0.1, 0.09, 0.01, -0.03, 0.4);
    expect(c.sxx).toBeCloseTo(0.08, 12);
    expect(c.syy).toBeCloseTo(0.08, 12);
    expect(c.sxy).toBeCloseTo(0, 12);
    const a = leanAlpha(0.3, -0.1, 0.09, 0.01, -0.03, 0.4);
    expect(a.alpha).toBeCloseTo(0.4, 12);
    expect(a.alphaMajor).toBeCloseTo(0.4, 6);
    expect(a.alphaMinor).toBeCloseTo(0.4, 6);
  });

  it('a diagonal ridge: principal axes along ±45°, LEAN trace = CLEAN variance', () => {
    // slopes ±t(1, 1)/√2 in equal parts: B = 0, M = t²/2 · [[1, 1], [1, 1]]
    const t2 = 0.25;
    const c = leanCovariance(0, 0, t2 / 2, t2 / 2, t2 / 2, 0.2);
    expect(c.major).toBeCloseTo(t2 + 0.02, 12);
    expect(c.minor).toBeCloseTo(0.02, 12);
    expect(leanAlpha(0, 0, t2 / 2, t2 / 2, t2 / 2, 0.2).alpha).toBeCloseTo(cleanAlpha(0, 0, t2, 0.2), 12);
    expect(cleanVariance(0, 0, t2)).toBe(t2);
  });

  it('quantized moments that give a negative variance are clamped (det Σ ≥ 0)', () => {
    const c = leanCovariance(0.5, 0.5, 0.249, 0.251, 0.3, 0.1);
    expect(c.sxx).toBeCloseTo(0.005, 12);
    expect(c.minor).toBeGreaterThanOrEqual(0.005 - 1e-12);
    expect(cleanVariance(0.5, 0.5, 0.49)).toBe(0);
  });
});

describe('2-channel reconstruction', () => {
  it('z = √(1 − x² − y²) gives unit length; clamps when x² + y² > 1', () => {
    for (const [x, y] of [[0, 0], [0.3, -0.4], [0.7, 0.7]]) expect(Math.hypot(x, y, reconstructZ(x, y))).toBeCloseTo(1, 15);
    expect(reconstructZ(0.8, 0.8)).toBe(0);
  });
});
