// Float64 Fresnel functions against an independent 50-digit oracle (tests/unit/oracle).
// Every case is deterministic (seeded PRNG). Tolerance is absolute 1e-12 on reflectances in
// [0, 1]: ~4 orders of magnitude above float64 rounding, ~5 below float32, so it can fail.
import { describe, it, expect, afterAll } from 'vitest';
import {
  fresnelExact,
  fresnelPolarized,
  fresnelConductor,
  fresnelConductorPolarized,
  fresnelSchlick,
} from '../../src/optics/fresnel.js';
import {
  D,
  exactDecimal,
  dielectricR,
  dielectricSP,
  conductorR,
  conductorSP,
  absError,
} from './oracle/fresnelOracle.js';

const TOL = 1e-12;
const CONSISTENCY_TOL = 1e-15; // fresnelExact vs mean of fresnelPolarized (two float64 formulas)

/** mulberry32: small, seedable, identical on every platform (Math.random is neither). */
function mulberry32(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const rng = mulberry32(0x5eed_f00d);
const cosDeg = (deg) => Math.cos((deg * Math.PI) / 180);
// Fixed angles: normal, mid-range and grazing down to 89.999°, plus cos = 1 and cos = 0 exactly.
const FIXED_DEG = [1, 10, 20, 30, 40, 45, 50, 60, 70, 75, 80, 85, 88, 89, 89.5, 89.9, 89.99, 89.999];
const FIXED_COS = [1, 0, ...FIXED_DEG.map(cosDeg)];
// Half uniform in cos, half uniform in angle (the latter crowds the grazing end).
const randomCos = () => (rng() < 0.5 ? rng() : Math.cos(rng() * (Math.PI / 2)));
const randomIndex = () => 1 + 1.5 * rng();
/** Neighbouring doubles: checks just either side of the float64 critical cosine. */
function nextDouble(x, dir) {
  const v = new DataView(new ArrayBuffer(8));
  v.setFloat64(0, x);
  v.setBigUint64(0, v.getBigUint64(0) + (dir > 0 ? 1n : -1n)); // valid for x > 0
  return v.getFloat64(0);
}

function buildDielectricCases() {
  const cases = [];
  const add = (group, ci, nI, nT) => cases.push({ group, ci, nI, nT });
  const both = (a, b) => [[a, b], [b, a]];
  const named = [[1, 1.5, 'air-glass'], [1, 1.333, 'air-water'], [1, 2.417, 'air-diamond']];
  for (const [a, b, name] of named) {
    for (const [nI, nT] of both(a, b)) {
      for (const ci of FIXED_COS) add(`${name} fixed angles`, ci, nI, nT);
      for (let i = 0; i < 15; i++) add(`${name} random angles`, randomCos(), nI, nT);
    }
  }
  const randomPairs = [];
  for (let i = 0; i < 70; i++) randomPairs.push([randomIndex(), randomIndex()]);
  for (const [a, b] of randomPairs) {
    for (const [nI, nT] of both(a, b)) {
      add('random pairs in [1, 2.5]', randomCos(), nI, nT);
      add('random pairs in [1, 2.5]', randomCos(), nI, nT);
    }
  }
  // Nearly matched media: R is tiny except near grazing, and g ≈ c invites cancellation.
  const near = [[1.31, 1.333], [1.5, 1.5001], [1.333, 1.3330000001], [1, 1.000293]];
  for (const [a, b] of near) {
    for (const [nI, nT] of both(a, b)) for (const ci of FIXED_COS) add('nearly matched', ci, nI, nT);
  }
  // Critical angle from the dense side: the g² → 0 edge of total internal reflection.
  const dense = [...named.map(([a, b]) => [b, a]), ...near.map(([a, b]) => [b, a])];
  for (let i = 0; i < 20; i++) {
    const [a, b] = [randomIndex(), randomIndex()];
    dense.push(a > b ? [a, b] : [b, a]);
  }
  for (const [nI, nT] of dense) {
    const tc = Math.asin(nT / nI);
    const cc = Math.sqrt((nI - nT) * (nI + nT)) / nI; // cos θc without going through asin
    for (const d of [-1e-6, 1e-6, -1e-9, 1e-9]) add('critical angle', Math.cos(tc + d), nI, nT);
    for (const ci of [Math.cos(tc), cc, nextDouble(cc, -1), nextDouble(cc, 1)]) {
      add('critical angle', ci, nI, nT);
    }
  }
  // Brewster angle, where Rp = 0 and rp's numerator cancels; ± 1e-6 rad around it.
  const brewsterPairs = [...named.flatMap(([a, b]) => both(a, b)), ...near.flatMap(([a, b]) => both(a, b))];
  for (let i = 0; i < 20; i++) brewsterPairs.push([randomIndex(), randomIndex()]);
  for (const [nI, nT] of brewsterPairs) {
    const tb = Math.atan2(nT, nI);
    for (const d of [0, -1e-6, 1e-6]) add('Brewster angle', Math.cos(tb + d), nI, nT);
  }
  return cases;
}

const METALS = [
  ['gold 650nm', 0.156, 3.602],
  ['gold 550nm', 0.424, 2.472],
  ['gold 450nm', 1.383, 1.916],
  ['silver', 0.052, 4.409],
  ['copper', 0.238, 3.626],
  ['aluminium', 1.558, 7.712],
  ['iron', 2.911, 3.089],
];

// n > k > 0 (weak absorbers: semiconductors, tinted glass), where a² comes from (S + t0)/2 and b²
// from n²k²/a² (t0 = n² − k² − sin²θ ≥ 0), the branch no metal above reaches; n = 1.2, k = 0.8 has
// t0 change sign at sin²θ = 0.8, so it takes each branch on either side of 63.4°.
const WEAK_ABSORBERS = [
  ['n > k > 0: n = 2.5, k = 0.5', 2.5, 0.5],
  ['n > k > 0: n = 1.5, k = 0.1', 1.5, 0.1],
  ['n > k > 0: n = 4.3, k = 0.07 (silicon-like)', 4.3, 0.07],
  ['n > k > 0: n = 1.5, k = 1e-4', 1.5, 1e-4],
  ['n > k > 0: n = 1.2, k = 0.8', 1.2, 0.8],
];

function buildConductorCases() {
  const cases = [];
  for (const [group, n, k] of [...METALS, ...WEAK_ABSORBERS]) {
    for (const ci of FIXED_COS) cases.push({ group, ci, n, k });
    for (let i = 0; i < 20; i++) cases.push({ group, ci: randomCos(), n, k });
  }
  return cases;
}

const dielectricCases = buildDielectricCases();
const conductorCases = buildConductorCases();
/** Cases by group, in first-seen order (Map.groupBy is not in Node 20). */
function groupBy(cases) {
  const groups = new Map();
  for (const c of cases) groups.set(c.group, [...(groups.get(c.group) ?? []), c]);
  return groups;
}

// Worst absolute error per function, over all cases, for the summary line.
const worst = {};
function track(name, err, inputs) {
  if (!worst[name] || err > worst[name].err) worst[name] = { err, inputs };
}
const fmt = (o) => Object.entries(o).map(([k, v]) => `${k}=${v}`).join(', ');

function inUnit(x) {
  return typeof x === 'number' && x >= 0 && x <= 1;
}

describe('fresnel.js (float64) against the 50-digit decimal.js oracle', () => {
  afterAll(() => {
    const parts = Object.entries(worst).map(([f, w]) => `${f} ${w.err.toExponential(2)} at (${fmt(w.inputs)})`);
    const total = dielectricCases.length + conductorCases.length;
    console.log(`[fresnel oracle] ${total} cases; worst |error|: ${parts.join('; ')}`);
  });

  it('covers about 1,450 deterministic cases, conductors on both sides of t0 = n² − k² − sin²θ = 0', () => {
    expect(dielectricCases.length + conductorCases.length).toBeGreaterThanOrEqual(1400);
    const t0 = ({ ci, n, k }) => n * n - k * k - (1 - ci * ci);
    expect(conductorCases.filter((c) => c.k > 0 && t0(c) >= 0).length).toBeGreaterThan(150);
    expect(conductorCases.filter((c) => t0(c) < 0).length).toBeGreaterThan(250);
  });

  for (const [group, cases] of groupBy(dielectricCases)) {
    it(`dielectric: ${group} (${cases.length} cases)`, () => {
      const failures = [];
      for (const { ci, nI, nT } of cases) {
        const inputs = { cosThetaI: ci, nI, nT };
        const r = fresnelExact(ci, nI, nT);
        const { s, p } = fresnelPolarized(ci, nI, nT);
        const sp = dielectricSP(ci, nI, nT);
        const errs = {
          fresnelExact: absError(r, dielectricR(ci, nI, nT)),
          'fresnelPolarized.s': absError(s, sp.s),
          'fresnelPolarized.p': absError(p, sp.p),
        };
        for (const [f, e] of Object.entries(errs)) {
          track(f, e, inputs);
          if (!(e <= TOL)) failures.push(`${f}(${fmt(inputs)}) error ${e}`);
        }
        const mean = 0.5 * (s + p);
        if (!(Math.abs(r - mean) <= CONSISTENCY_TOL)) {
          failures.push(`fresnelExact ≠ (s+p)/2 at (${fmt(inputs)}): ${r} vs ${mean}`);
        }
        for (const [f, v] of [['fresnelExact', r], ['s', s], ['p', p]]) {
          if (!inUnit(v)) failures.push(`${f} = ${v} outside [0, 1] at (${fmt(inputs)})`);
        }
      }
      expect(failures).toEqual([]);
    });
  }

  for (const [group, cases] of groupBy(conductorCases)) {
    it(`conductor: ${group} (${cases.length} cases)`, () => {
      const failures = [];
      for (const { ci, n, k } of cases) {
        const inputs = { cosThetaI: ci, n, k };
        const r = fresnelConductor(ci, n, k);
        const pol = fresnelConductorPolarized(ci, n, k);
        const sp = conductorSP(ci, n, k);
        const errs = {
          fresnelConductor: absError(r, conductorR(ci, n, k)),
          'fresnelConductorPolarized.s': absError(pol.s, sp.s),
          'fresnelConductorPolarized.p': absError(pol.p, sp.p),
        };
        for (const [f, e] of Object.entries(errs)) {
          track(f, e, inputs);
          if (!(e <= TOL)) failures.push(`${f}(${fmt(inputs)}) error ${e}`);
        }
        for (const [f, v] of [['fresnelConductor', r], ['s', pol.s], ['p', pol.p]]) {
          if (!inUnit(v)) failures.push(`${f} = ${v} outside [0, 1] at (${fmt(inputs)})`);
        }
      }
      expect(failures).toEqual([]);
    });
  }
});

// The oracle is only worth trusting if it is right on closed forms and the harness can fail.
describe('the oracle itself', () => {
  it('converts doubles exactly (not via their shortest decimal string)', () => {
    expect(exactDecimal(0.1).toFixed()).toBe('0.1000000000000000055511151231257827021181583404541015625');
    expect(exactDecimal(0.1).eq(new D(0.1))).toBe(false);
    // Smallest subnormal: exactly 2^-1074, so times the exact integer 2^1074 it is exactly 1.
    expect(exactDecimal(Number.MIN_VALUE).times(new D((2n ** 1074n).toString())).eq(1)).toBe(true);
    const r = mulberry32(7);
    for (let i = 0; i < 200; i++) {
      const x = (r() - 0.5) * 2 ** Math.floor(r() * 200 - 100);
      expect(exactDecimal(x).toNumber()).toBe(x);
    }
  });

  it('matches closed forms: R0, Brewster, TIR, matched media', () => {
    expect(dielectricR(1, 1, 1.5).toString()).toBe('0.04'); // ((1.5 − 1)/(1.5 + 1))²
    expect(dielectricR(1, 1.5, 1).toString()).toBe('0.04');
    const cb = Math.cos(Math.atan(1.5)); // float64 Brewster angle: Rp ~ (1e-16)², not 0
    expect(dielectricSP(cb, 1, 1.5).p.lt(1e-30)).toBe(true);
    expect(dielectricR(0.5, 1.5, 1).eq(1)).toBe(true); // 60° > θc = 41.8°
    expect(dielectricR(0, 1.333, 1.333).eq(0)).toBe(true);
    expect(conductorR(1, 1, 0).abs().lt(1e-45)).toBe(true);
  });

  it('conductor with k = 0 reduces to the dielectric from air, incl. TIR for n < 1', () => {
    for (const ci of [1, 0.7, 0.3, 0.01, 0]) {
      for (const n of [1.5, 2.417, 0.8]) {
        expect(conductorR(ci, n, 0).minus(dielectricR(ci, 1, n)).abs().lt(1e-45)).toBe(true);
      }
    }
  });

  it('1e-12 is tight enough to reject Schlick and float32-rounded results', () => {
    const ci = cosDeg(70);
    expect(absError(fresnelSchlick(ci, 1, 1.5), dielectricR(ci, 1, 1.5))).toBeGreaterThan(TOL);
    const f32 = dielectricCases.filter(({ ci: c, nI, nT }) => {
      const r = fresnelExact(c, nI, nT);
      return absError(Math.fround(r), dielectricR(c, nI, nT)) > TOL;
    });
    expect(f32.length).toBeGreaterThan(dielectricCases.length / 2);
  });
});
