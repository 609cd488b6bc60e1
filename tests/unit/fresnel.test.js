import { describe, expect, it } from 'vitest';
import {
  brewsterAngle, conductorNormalIncidence, criticalAngle, fresnelConductor, fresnelExact,
  fresnelPolarized, fresnelSchlick, fresnelSchlickExp2, fresnelSchlickTIR, fresnelTransmittance,
  normalIncidence, snellCosT,
} from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;
const cosDeg = (d) => Math.cos(d * DEG);
const angles = Array.from({ length: 901 }, (_, i) => i / 10); // 0° to 90° by 0.1°
const pairs = [[1, 1.5], [1.5, 1], [1, 1.333], [1.333, 1], [1, 2.417], [2.417, 1], [1.31, 1.333], [1.333, 1.31]];

describe('landmarks', () => {
  it('R0 is 0.04 for n = 1.5, the same both ways', () => {
    expect(normalIncidence(1, 1.5)).toBeCloseTo(0.04, 15);
    expect(normalIncidence(1.5, 1)).toBeCloseTo(0.04, 15);
    expect(fresnelExact(1, 1, 1.5)).toBeCloseTo(0.04, 15);
    expect(fresnelExact(1, 1.5, 1)).toBeCloseTo(0.04, 15);
  });
  it('critical angle glass to air is 41.8103° and none from air', () => {
    expect(criticalAngle(1.5, 1) / DEG).toBeCloseTo(41.8103, 4);
    expect(criticalAngle(1, 1.5)).toBeNull();
    expect(criticalAngle(1.5, 1.5)).toBeNull();
  });
  it('Brewster angle air to glass is 56.3099° and Rp vanishes there', () => {
    const b = brewsterAngle(1, 1.5);
    expect(b / DEG).toBeCloseTo(56.3099, 4);
    expect(fresnelPolarized(Math.cos(b), 1, 1.5).p).toBeLessThan(1e-30);
    expect(fresnelPolarized(Math.cos(b), 1, 1.5).s).toBeGreaterThan(0.14);
  });
  it('R(90°) = 1 for any mismatch, and the lecture-slide values at 1.5', () => {
    for (const [a, b] of pairs) expect(fresnelExact(0, a, b)).toBe(1);
    const expected = { 30: 0.04152, 45: 0.05024, 60: 0.08919, 75: 0.2531, 80: 0.3877, 85: 0.6128, 89: 0.9042 };
    for (const [deg, r] of Object.entries(expected)) expect(fresnelExact(cosDeg(+deg), 1, 1.5)).toBeCloseTo(r, 4);
  });
});

describe('identities', () => {
  it('the c/g form equals (Rs + Rp)/2', () => {
    for (const [a, b] of pairs) {
      for (const t of angles) {
        const { s, p } = fresnelPolarized(cosDeg(t), a, b);
        expect(Math.abs(fresnelExact(cosDeg(t), a, b) - 0.5 * (s + p))).toBeLessThan(1e-14);
      }
    }
  });
  it('R + T = 1 for each polarization, and T = 0 under total internal reflection', () => {
    for (const [a, b] of pairs) {
      for (const t of angles) {
        const r = fresnelPolarized(cosDeg(t), a, b);
        const tr = fresnelTransmittance(cosDeg(t), a, b);
        expect(r.s + tr.s).toBeCloseTo(1, 13);
        expect(r.p + tr.p).toBeCloseTo(1, 13);
      }
    }
    expect(fresnelTransmittance(cosDeg(60), 1.5, 1)).toEqual({ s: 0, p: 0, unpolarized: 0 });
  });
  it("Snell's law: nI sin θi = nT sin θt, and none past the critical angle", () => {
    const ct = snellCosT(cosDeg(30), 1, 1.5);
    expect(Math.sin(Math.acos(ct)) * 1.5).toBeCloseTo(Math.sin(30 * DEG), 14);
    expect(snellCosT(cosDeg(45), 1.5, 1)).toBeNull();
  });
});

describe('total internal reflection and matched media', () => {
  it('R = 1 past the critical angle, below 1 just inside it', () => {
    const tc = criticalAngle(1.5, 1) / DEG;
    expect(fresnelExact(cosDeg(tc + 1e-6), 1.5, 1)).toBe(1);
    expect(fresnelExact(cosDeg(tc - 0.01), 1.5, 1)).toBeLessThan(1);
    expect(fresnelExact(cosDeg(60), 1.5, 1)).toBe(1);
  });
  it('equal indices reflect nothing at every angle, grazing included', () => {
    for (const t of [...angles, 89.9999999]) expect(fresnelExact(cosDeg(t), 1.333, 1.333)).toBe(0);
    expect(fresnelExact(0, 1.5, 1.5)).toBe(0);
    expect(fresnelExact(1e-9, 1.5, 1.5)).toBe(0);
  });
  it('the lecture order 1 + c² − m² fails at grazing for matched media; the safe order does not', () => {
    const literal = (ci, nI, nT) => {
      const m = nI / nT;
      const c = m * ci;
      const g2 = 1 + c * c - m * m;
      if (g2 <= 0) return 1;
      const g = Math.sqrt(g2);
      const b = (c * (g + c) - m * m) / (c * (g - c) + m * m);
      return 0.5 * ((g - c) / (g + c)) ** 2 * (1 + b * b);
    };
    expect(literal(1e-9, 1.5, 1.5)).toBe(1); // c² vanishes beside 1: g = 0, the formula says "mirror"
    expect(fresnelExact(1e-9, 1.5, 1.5)).toBe(0);
    // Nearly matched: agrees with the s/p form (which needs no such care) to the last digits.
    const sp = fresnelPolarized(1e-3, 1.333, 1.3330001);
    expect(fresnelExact(1e-3, 1.333, 1.3330001)).toBeCloseTo(0.5 * (sp.s + sp.p), 14);
  });
  it('Schlick has no TIR; Schlick on cos θt does', () => {
    const tc = criticalAngle(1.5, 1);
    const c = Math.cos(tc) + 1e-12;
    expect(1 - fresnelSchlick(c, 1.5, 1)).toBeGreaterThan(0.95);
    expect(fresnelSchlickTIR(Math.cos(tc + 1e-6), 1.5, 1)).toBe(1);
    for (const t of angles) expect(fresnelSchlickTIR(cosDeg(t), 1, 1.5)).toBe(fresnelSchlick(cosDeg(t), 1, 1.5));
    // Inside, its error equals the outside error at the transmitted angle: at most 0.036 for 1.5.
    let worst = 0;
    for (const t of angles) worst = Math.max(worst, Math.abs(fresnelSchlickTIR(cosDeg(t), 1.5, 1) - fresnelExact(cosDeg(t), 1.5, 1)));
    expect(worst).toBeGreaterThan(0.03);
    expect(worst).toBeLessThan(0.037);
  });
});

describe('Schlick forms', () => {
  it('Schlick error from air into 1.5 peaks near 0.0357 at about 85°', () => {
    let worst = { e: 0, t: 0 };
    for (let t = 0; t <= 90; t += 0.001) {
      const e = Math.abs(fresnelSchlick(cosDeg(t), 1, 1.5) - fresnelExact(cosDeg(t), 1, 1.5));
      if (e > worst.e) worst = { e, t };
    }
    expect(worst.e).toBeCloseTo(0.0357, 4);
    expect(worst.t).toBeCloseTo(85.0, 0);
  });
  it("the exp2 form is three.js's F_Schlick: exact at both ends, close in between", () => {
    expect(fresnelSchlickExp2(0, 1, 1.5)).toBe(1);
    expect(fresnelSchlickExp2(1, 1, 1.5)).toBeCloseTo(0.04 + 0.96 * 2 ** -12.53789, 12);
    for (const t of angles) expect(Math.abs(fresnelSchlickExp2(cosDeg(t), 1, 1.5) - fresnelSchlick(cosDeg(t), 1, 1.5))).toBeLessThan(0.02);
  });
});

describe('conductors', () => {
  it('R0 = ((n−1)² + k²)/((n+1)² + k²) for gold, and reduces to the dielectric when k = 0', () => {
    const [n, k] = [0.156, 3.602];
    expect(fresnelConductor(1, n, k)).toBeCloseTo(((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k), 15);
    expect(conductorNormalIncidence(n, k)).toBeCloseTo(0.9564, 4);
    for (const t of angles) expect(fresnelConductor(cosDeg(t), 1.5, 0)).toBeCloseTo(fresnelExact(cosDeg(t), 1, 1.5), 14);
    expect(fresnelConductor(0, n, k)).toBe(1);
  });
  it('metals dip below F0 before grazing (what Schlick cannot show)', () => {
    const [n, k] = [1.558, 7.712]; // aluminium, red
    expect(fresnelConductor(cosDeg(82), n, k)).toBeLessThan(fresnelConductor(1, n, k));
  });
});

describe('the contract every function keeps', () => {
  const fns = { fresnelExact, fresnelSchlick, fresnelSchlickTIR, fresnelSchlickExp2, fresnelConductor };
  it('clamps cos θ to [0, 1]', () => {
    for (const [name, f] of Object.entries(fns)) {
      expect(f(1 + 2 ** -23, 1, 1.5), name).toBe(f(1, 1, 1.5));
      expect(f(-0.05, 1, 1.5), name).toBe(f(0, 1, 1.5));
    }
  });
  it('throws a RangeError naming the bad argument', () => {
    for (const [name, f] of Object.entries(fns)) {
      expect(() => f(NaN, 1, 1.5), name).toThrow(/cosThetaI/);
      expect(() => f(Infinity, 1, 1.5), name).toThrow(RangeError);
      expect(() => f('0.5', 1, 1.5), name).toThrow(RangeError);
    }
    expect(() => fresnelExact(0.5, 0, 1.5)).toThrow(/nI/);
    expect(() => fresnelExact(0.5, 1, -1)).toThrow(/nT/);
    expect(() => fresnelPolarized(0.5, 1, NaN)).toThrow(/nT/);
    expect(() => normalIncidence(Infinity, 1)).toThrow(/nI/);
    expect(() => criticalAngle(1, 0)).toThrow(/nT/);
    expect(() => brewsterAngle(null, 1)).toThrow(/nI/);
    expect(() => fresnelConductor(0.5, 0, 1)).toThrow(/\bn\b/);
    expect(() => fresnelConductor(0.5, 1, -1)).toThrow(/\bk\b/);
    expect(() => snellCosT(0.5, 1, undefined)).toThrow(/nT/);
  });
  it('results stay in [0, 1] over random inputs', () => {
    let seed = 7;
    const rand = () => ((seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31);
    for (let i = 0; i < 5000; i += 1) {
      const c = rand() * 1.2 - 0.1;
      const a = 0.3 + rand() * 3;
      const b = 0.3 + rand() * 3;
      for (const f of [fresnelExact, fresnelSchlick, fresnelSchlickTIR, fresnelSchlickExp2]) {
        const r = f(c, a, b);
        expect(r >= 0 && r <= 1).toBe(true);
      }
      const sp = fresnelPolarized(c, a, b);
      expect(sp.s >= 0 && sp.s <= 1 && sp.p >= 0 && sp.p <= 1).toBe(true);
      const m = fresnelConductor(c, a, rand() * 8);
      expect(m >= 0 && m <= 1).toBe(true);
    }
  });
});
