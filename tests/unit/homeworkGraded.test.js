// Every homework question grades a physical quantity it declares (`graded`, in its source), and here
// that quantity is computed again without the lab's code: from the 50-digit optics oracle
// (tests/unit/oracle) or from the textbook formula written out below. A numeric or predicted answer
// must match it far inside the question's tolerance; in a choice question exactly the option the
// physics picks must hold. Every parameter set a seed can draw is checked, and a question without a
// check here fails the last test.
import { describe, expect, it } from 'vitest';
import { QUESTIONS, questionById } from '../../src/homework/questions.js';
import { allParams } from './questionParamSets.js';
import { columnCos } from '../../src/methods/classifyGrid.js';
import { fresnelR } from './oracle/rightAnswers.js';
import { brewsterDegrees, conductorR, cosOfDegrees, criticalDegrees, dielectricR, dielectricSP } from './oracle/fresnelOracle.js';
import materials from '../../src/optics/materials.json';
import { roadSpot } from './oracle/roadOracle.js';

const DEG = Math.PI / 180;
const num = (decimal) => decimal.toNumber();
const R = (thetaDeg, nI, nT) => num(dielectricR(cosOfDegrees(thetaDeg), nI, nT));
const metal = (id) => materials.metals.find((m) => m.id === id);
const dielectricN = (id) => materials.dielectrics.find((m) => m.id === id).n['589'];

/** θ in [lo, hi] where the increasing or decreasing f crosses level, by bisection. */
function crossing(f, level, lo, hi) {
  const below = f(lo) < level;
  let [a, b] = [lo, hi];
  for (let i = 0; i < 60; i += 1) {
    const m = (a + b) / 2;
    if ((f(m) < level) === below) a = m;
    else b = m;
  }
  return (a + b) / 2;
}

/** The option ids of a choice question that hold for p. */
const holding = (q, p) => q.options(p).filter((o) => o.holds(p)).map((o) => o.id);

// Plain float64 textbook forms, for grid searches the 50-digit oracle would make slow (Hecht, Optics, §4.6).
const fresnelPlain = fresnelR;
const schlickPlain = (thetaDeg, nI, nT) => {
  const r0 = ((nT - nI) / (nT + nI)) ** 2;
  return r0 + (1 - r0) * (1 - Math.cos(thetaDeg * DEG)) ** 5;
};

/** For each question id: a check of its graded quantity for one parameter set p. */
const CHECKS = {
  'mip-renormalize': (q, p) => {
    const L = Math.cos(p.tiltDeg * DEG); // |(n1 + n2)/2| for unit normals ±t from the mean
    expect(L).toBeLessThan(1);
    const sigma2 = (1 - L) / L; // Toksvig 2004
    expect(p.s / (1 + p.s * sigma2)).toBeLessThan(p.s);
    expect(holding(q, p)).toEqual(['loses-roughness']);
  },
  'toksvig-exponent': (q, p) => {
    const sigma2 = (1 - p.L) / p.L;
    expect(Math.abs(q.expected(p) - p.s / (1 + p.s * sigma2))).toBeLessThan(1e-9);
  },
  'asphalt-outshine': (q, p) => {
    const spot = (b) => roadSpot(b, { sunEl: p.sunEl, roughness: 0.8, nT: p.nT });
    const share = (b) => spot(b).specular / (spot(b).specular + spot(b).diffuse);
    const truth = crossing(share, 0.5, 1, 90);
    expect(Math.abs(q.expected(p) - truth)).toBeLessThan(1e-6);
    // One answer: from the road straight below to the horizon the two parts are equal once only.
    let crossings = 0;
    for (let b = 0.05; b < 90; b += 0.05) if ((share(b) > 0.5) !== (share(b + 0.05) > 0.5)) crossings += 1;
    expect(crossings).toBe(1);
    // Measured, not predicted: the panel shows its answer only once a prediction is locked.
    expect(q.kind).toBe('numeric');
    // The readout gives the angle to 0.1° and both parts to 3 decimals: wherever it shows them equal, the
    // angle it shows is within the tolerance; and the band where it does is no wider than that allows.
    const shownEqual = [];
    for (let b = truth - 3; b <= truth + 3; b += 0.001) {
      if (spot(b).specular.toFixed(3) === spot(b).diffuse.toFixed(3)) shownEqual.push(Number(b.toFixed(1)));
    }
    expect(shownEqual.length).toBeGreaterThan(0);
    for (const shown of shownEqual) expect(Math.abs(shown - truth), `${JSON.stringify(p)} at ${shown}°`).toBeLessThanOrEqual(q.tolerance);
    expect(q.tolerance).toBeLessThan(1);
    expect(q.prompt(p)).toContain(`within ${q.tolerance}°`);
  },
  'phong-grazing': (q, p) => {
    const r0 = ((p.nT - 1) / (p.nT + 1)) ** 2;
    expect(R(85, 1, p.nT)).toBeGreaterThan(4 * r0); // Phong × F grows many times; plain Phong stays R0
    expect(holding(q, p)).toEqual(['fresnel-grows']);
  },
  'split-half': (q, p) => expect(Math.abs(q.expected(p) - crossing((t) => fresnelPlain(t, 1, p.nT), 0.5, 0, 90))).toBeLessThan(1e-6),
  'snell-angle': (q, p) => expect(Math.abs(q.expected(p) - Math.asin(Math.sin(p.theta * DEG) / p.nT) / DEG)).toBeLessThan(1e-9),
  'critical-predict': (q, p) => expect(Math.abs(q.expected(p) - num(criticalDegrees(p.nI, 1)))).toBeLessThan(1e-9),
  'critical-angle': (q, p) => expect(Math.abs(q.expected(p) - num(criticalDegrees(p.nI, 1)))).toBeLessThan(1e-9),
  'schlick-worst': (q, p) => {
    let best = { gap: -1, theta: 0 };
    for (let i = 0; i <= 90000; i += 1) {
      const t = i / 1000;
      const gap = Math.abs(fresnelPlain(t, 1, p.nT) - schlickPlain(t, 1, p.nT));
      if (gap > best.gap) best = { gap, theta: t };
    }
    expect(Math.abs(q.expected(p) - best.theta)).toBeLessThan(0.002);
  },
  'r0-materials': (q, p) => {
    const r0 = (id) => ((dielectricN(id) - 1) / (dielectricN(id) + 1)) ** 2;
    expect(r0('water')).toBeLessThan(r0('glass'));
    expect(r0('glass')).toBeLessThan(r0('diamond'));
    expect(Math.abs(r0('diamond') - 0.04)).toBeGreaterThan(0.1);
    expect(holding(q, p)).toEqual(['depends-on-n']);
    // What the right option says of R0 = ((r − 1)/(r + 1))², r = n_t/n_i: the same for r and 1/r, and larger the
    // further r lies from 1 on either side.
    const ofRatio = (r) => ((r - 1) / (r + 1)) ** 2;
    for (let r = 1.05; r < 4; r += 0.05) {
      expect(ofRatio(1 / r)).toBeCloseTo(ofRatio(r), 14);
      expect(ofRatio(r + 0.05)).toBeGreaterThan(ofRatio(r));
      expect(ofRatio(1 / (r + 0.05))).toBeGreaterThan(ofRatio(1 / r));
    }
    const right = q.options(p).find((o) => o.id === 'depends-on-n').text(p);
    expect(right).toContain('the further n_t/n_i lies from 1 on either side (a ratio and its inverse give the same R(0°))');
  },
  'exact-rp-rs': (q, p) => {
    const { s, p: rp } = dielectricSP(cosOfDegrees(p.theta), 1, p.nT);
    expect(Math.abs(q.expected(p) - num(s.minus(rp)))).toBeLessThan(1e-12);
  },
  'brewster-predict': (q, p) => expect(Math.abs(q.expected(p) - num(brewsterDegrees(1, p.nT)))).toBeLessThan(1e-9),
  'brewster-exact': (q, p) => expect(Math.abs(q.expected(p) - num(brewsterDegrees(p.nI, p.nT)))).toBeLessThan(1e-9),
  'exact-r': (q, p) => expect(Math.abs(q.expected(p) - R(p.theta, 1, p.nT))).toBeLessThan(1e-12),
  'matched-grazing': (q, p) => {
    expect(R(89.9, p.n, p.n)).toBe(0);
    expect(holding(q, p)).toEqual(['zero']);
  },
  'schlick-error': (q, p) => {
    expect(Math.abs(q.expected(p) - Math.abs(R(p.theta, 1, p.nT) - schlickPlain(p.theta, 1, p.nT)))).toBeLessThan(1e-12);
  },
  'schlick-inside': (q, p) => {
    expect(p.theta).toBeGreaterThan(num(criticalDegrees(1.5, 1)));
    expect(R(p.theta, 1.5, 1)).toBe(1);
    expect(schlickPlain(p.theta, 1.5, 1)).toBeLessThan(0.9);
    expect(holding(q, p)).toEqual(['misses-tir']);
  },
  'r0-value': (q, p) => expect(Math.abs(q.expected(p) - ((p.nT - 1) / (p.nT + 1)) ** 2)).toBeLessThan(1e-15),
  'rim-scaling': (q, p) => {
    expect(2 * R(85, 1, p.nT)).toBeGreaterThan(1);
    expect(holding(q, p)).toEqual(['energy']);
  },
  'metal-grazing': (q, p) => {
    const m = metal(p.metal);
    const at = (t) => m.n.map((n, i) => num(conductorR(cosOfDegrees(t), n, m.k[i])));
    const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);
    expect(Math.min(...at(89))).toBeGreaterThan(0.9);
    expect(spread(at(89))).toBeLessThan(spread(at(0)) / 4);
    expect(holding(q, p)).toEqual(['towards-white']);
  },
  'metal-r0': (q, p) => {
    const { n: [, n], k: [, k] } = metal(p.metal);
    expect(Math.abs(q.expected(p) - ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k))).toBeLessThan(1e-12);
  },
  'schlick-visible': (q, p) => {
    // sRGB encoding (IEC 61966-2-1), 8-bit codes at display white, over air → n 1.3 … 1.7 and every angle.
    const enc = (x) => (x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055);
    let worst = 0;
    for (let n = 1.3; n <= 1.7001; n += 0.05) {
      for (let i = 0; i <= 9000; i += 1) {
        const t = i / 100;
        worst = Math.max(worst, 255 * Math.abs(enc(schlickPlain(t, 1, n)) - enc(fresnelPlain(t, 1, n))));
      }
    }
    expect(worst).toBeGreaterThan(2);
    expect(holding(q, p)).toEqual(['visible']);
  },
  'lecture-order': (q, p) => {
    // float32, as a highp shader rounds: 1 + c² rounds to 1 once c² < 2⁻²⁴, so g = sqrt(1 + c² − 1) = 0, and
    // R = ½((g − c)/(g + c))²(1 + ((c(g + c) − 1)/(c(g − c) + 1))²) = ½·1·(1 + 1) = 1 where the exact R is 0.
    const f = Math.fround;
    const c = f(Math.cos(p.theta * DEG));
    expect(f(c * c)).toBeLessThan(2 ** -24);
    expect(f(1 + f(c * c))).toBe(1);
    expect(R(p.theta, p.n, p.n)).toBe(0);
    expect(holding(q, p)).toEqual(['one']);
  },
  'pow-above-one': (q, p) => {
    // 1.0000001 survives float32 (1 + 2⁻²³), so 1 − cos θ is negative: pow is undefined there (GLSL ES 3.00 §8.2).
    const c = Math.fround(1.0000001);
    expect(c).toBeGreaterThan(1);
    expect(Math.fround(1 - c)).toBeLessThan(0);
    expect(q.prompt(p)).toContain('1.0000001');
    expect(holding(q, p)).toEqual(['undefined']);
    // The answer says the stability map cannot show it: its θ = 0° column is cos θ = 1 exactly.
    expect(columnCos(0)).toBe(1);
  },
};

describe('every question grades the physical quantity it declares', () => {
  for (const q of QUESTIONS) {
    it(`${q.id}: ${q.graded?.slice(0, 60) ?? 'no declared quantity'}…`, () => {
      expect(typeof q.graded === 'string' && q.graded.length > 40, `${q.id} declares what it grades`).toBe(true);
      const check = CHECKS[q.id];
      expect(check, `${q.id} has an independent check here`).toBeTypeOf('function');
      for (const p of allParams(q, 'graded')) check(q, p);
    });
  }
  it('checks no question that is gone', () => {
    expect(Object.keys(CHECKS).filter((id) => !questionById(id))).toEqual([]);
  });
});
