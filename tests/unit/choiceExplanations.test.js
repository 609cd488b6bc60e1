// Every number in a choice question's explanations (the `why` of each option) is computed here again
// without the lab's code, from textbook formulas and the 50-digit optics oracle (tests/unit/oracle),
// for every parameter set a seed can draw: each explanation must hold the phrases written below, with
// their numbers, and no other number. Notation is no number (as in teachingText.test.js): digits in a
// name (float32, log2, N-BK7), 0 and 1, and the literal notation each question lists.
import { describe, expect, it } from 'vitest';
import { QUESTIONS } from '../../src/homework/questions.js';
import { allParams } from './questionParamSets.js';
import { conductorR, cosOfDegrees } from './oracle/fresnelOracle.js';
import { fresnelR } from './oracle/rightAnswers.js';
import materials from '../../src/optics/materials.json';

const DEG = Math.PI / 180;
const f = (x, d) => x.toFixed(d);
const R = (thetaDeg, nI, nT) => fresnelR(thetaDeg, nI, nT);
const r0 = (n) => ((n - 1) / (n + 1)) ** 2;
// Schlick, Computer Graphics Forum 13(3), 1994, on cos θ of the side the light comes from.
const schlick = (thetaDeg, nI, nT) => r0(nT / nI) + (1 - r0(nT / nI)) * (1 - Math.cos(thetaDeg * DEG)) ** 5;
const dielectricN = (id) => materials.dielectrics.find((m) => m.id === id).n['589'];
const metal = (id) => materials.metals.find((m) => m.id === id);
// sRGB encoding (IEC 61966-2-1) of a value clamped to [0, 1], in 8-bit codes.
const codes = (x) => {
  const v = Math.min(1, Math.max(0, x));
  return 255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055);
};

/** The numbers left once the phrases, the notation and names with digits are taken out (0 and 1 are notation). */
function unaccounted(text, phrases) {
  const rest = phrases.reduce((t, phrase) => t.replaceAll(phrase, ' '), text);
  return (rest.replace(/\p{L}+\d+/gu, '').match(/\d+(?:\.\d+)?/g) ?? []).filter((n) => n !== '0' && n !== '1');
}

/** Schlick's worst display error from air into n over every angle: codes and where (0.01° grid, float64). */
function schlickWorstAt(n) {
  let best = { codes: -1, theta: 0 };
  for (let i = 0; i <= 9000; i += 1) {
    const theta = i / 100;
    const c = Math.abs(codes(schlick(theta, 1, n)) - codes(R(theta, 1, n)));
    if (c > best.codes) best = { codes: c, theta };
  }
  return { ...best, n };
}
const PLASTIC = Array.from({ length: 9 }, (_, i) => 1.3 + 0.05 * i); // air → n 1.3 … 1.7, the prompt's range

/** The lecture's c/g form in float32 (every operation rounded as a highp shader rounds it), from air into n. */
function exactCgFloat32(cosTheta, n) {
  const F = Math.fround;
  const m = F(1 / n);
  const c = F(m * F(cosTheta));
  const g = F(Math.sqrt(F(F(F(1 - m) * F(1 + m)) + F(c * c))));
  const a = F(F(g - c) / F(g + c));
  const b = F(F(F(c * F(g + c)) - F(m * m)) / F(F(c * F(g - c)) + F(m * m)));
  return F(F(0.5 * F(a * a)) * F(1 + F(b * b)));
}

/** For each question: the phrases each option's explanation holds for p, and notation to leave alone. */
const PHRASES = {
  'mip-renormalize': (p) => {
    const L = Math.cos(p.tiltDeg * DEG); // |(n1 + n2)/2| for unit normals ±t from their mean
    const lowered = f(p.s / (1 + (p.s * (1 - L)) / L), 1); // Toksvig 2004: s' = s/(1 + s·σ²), σ² = (1 − L)/L
    return {
      'keeps-roughness': [`length ${f(L, 3)};`, `(${lowered} instead of ${p.s})`],
      'loses-roughness': [`length ${f(L, 3)} carries`, `exponent ${lowered} instead of ${p.s}`],
    };
  },
  'phong-grazing': (p) => {
    // The peak in the mirror direction: plain Phong is R0 at every elevation; Phong × F is F(90° − elevation).
    const [head, rim] = [r0(p.nT), R(85, 1, p.nT)];
    const both = `plain Phong ${f(head, 3)} → ${f(head, 3)}, Phong × F ${f(head, 3)} → ${f(rim, 3)}`;
    return {
      'fresnel-grows': [both, `n·l = sin 5° would see Phong × F grow only ×${f((rim * Math.sin(5 * DEG)) / head, 1)}`],
      'both-grow': [both],
      'both-fade': [both],
    };
  },
  'r0-materials': () => {
    const named = (id, name) => `${name} (n = ${f(dielectricN(id), 3)})`;
    const [water, glass, diamond] = ['water', 'glass', 'diamond'].map((id) => f(r0(dielectricN(id)), 3));
    return {
      'all-004': ['0.04 is R(0°)', `n = 1.5 exactly, ((n − 1)/(n + 1))² = ${f(r0(1.5), 3)}`, `${named('water', 'Water')} gives ${water}`,
        `${named('diamond', 'diamond')} ${diamond}`],
      'depends-on-n': [`${named('water', 'water')} gives ${water}`, `${named('glass', 'N-BK7 crown glass')} ${glass}`,
        `${named('diamond', 'diamond')} ${diamond}`],
      'none-head-on': [`${named('glass', 'N-BK7 crown glass')} still reflects ${glass}`],
    };
  },
  'matched-grazing': (p) => {
    const [r, fromAir] = [R(89.9, p.n, p.n), R(89.9, 1, p.n)];
    return {
      one: [`R = ${f(r, 3)} at every angle`, `from air into ${p.n}, R(89.9°) = ${f(fromAir, 3)}`],
      zero: [`(from air into ${p.n} it would be ${f(fromAir, 3)})`],
      half: [`R = ${f(r, 3)}:`],
    };
  },
  'schlick-inside': (p) => {
    const critical = Math.asin(1 / 1.5) / DEG;
    const gives = `Schlick on cos θ_i gives ${f(schlick(p.theta, 1.5, 1), 3)}`;
    return {
      good: [`critical angle (${f(critical, 1)}°) the exact R is ${f(R(p.theta, 1.5, 1), 3)}, ${gives}`],
      'misses-tir': [gives],
    };
  },
  'rim-scaling': (p) => {
    const rim = R(85, 1, p.nT);
    return {
      'scale-up': [`F at 85° is already ${f(rim, 3)}; doubled it is ${f(2 * rim, 3)}`, `the centre's ${f(r0(p.nT), 3)} doubles`],
      energy: [`2·F(85°) = ${f(2 * rim, 3)} > 1`, `(F(85°) = ${[1.33, 1.5, 2].map((n) => f(R(85, 1, n), 2)).join(', ')} for n = 1.33, 1.5, 2)`],
    };
  },
  'metal-grazing': (p) => {
    const m = metal(p.metal);
    const at = (theta) => m.n.map((n, i) => conductorR(cosOfDegrees(theta), n, m.k[i]).toNumber());
    const list = (rgb) => rgb.map((x) => f(x, 2)).join(', ');
    const grows = at(89).every((x, i) => x > at(0)[i]);
    return {
      'keeps-colour': [`head-on the channels are ${list(at(0))}; at 89° they are ${list(at(89))}`],
      'towards-white': [`at 89° the channels are ${list(at(89))}`],
      dark: [`${grows ? 'every channel grows' : 'the channels go'} from ${list(at(0))} head-on to ${list(at(89))} at 89°`],
    };
  },
  'schlick-visible': () => {
    const all = PLASTIC.map(schlickWorstAt);
    const worst = all.reduce((a, b) => (b.codes > a.codes ? b : a));
    const middle = all.filter((w) => w.theta < 70);
    const from = Math.min(...middle.map((w) => w.n));
    expect(all.filter((w) => w.n > from).every((w) => w.theta < 70)).toBe(true); // "from n = … up"
    expect(worst.n).toBe(Math.min(...PLASTIC)); // "the lowest index of the range"
    let exactWorst = 0;
    for (const n of PLASTIC) {
      for (let i = 0; i <= 9000; i += 1) {
        const theta = i / 100;
        exactWorst = Math.max(exactWorst, Math.abs(codes(exactCgFloat32(Math.cos(theta * DEG), n)) - codes(R(theta, 1, n))));
      }
    }
    expect(exactWorst).toBeLessThan(0.01);
    const at = `${f(worst.codes, 1)} codes (${f((100 * worst.codes) / 255, 1)} % of the range) at worst, near θ = ${f(worst.theta, 0)}° `
      + `for n = ${f(worst.n, 2)}`;
    const lo = Math.min(...middle.map((w) => w.theta));
    const hi = Math.max(...middle.map((w) => w.theta));
    return {
      invisible: [at],
      visible: [`${at}, the lowest index of the range`, `from n = ${f(from, 2)} up, each index's largest error sits at middle angles, `
        + `${f(lo, 0)}–${f(hi, 0)}°, not near grazing`, 'less than 0.01 codes at worst'],
    };
  },
  'lecture-order': (p) => {
    // float32: 1 + c² rounds to 1, so g = 0, (g − c)/(g + c) = −1 and (c(g + c) − 1)/(c(g − c) + 1) = −1: R = ½·1·(1 + 1).
    const F = Math.fround;
    const c = F(Math.cos(p.theta * DEG));
    expect(F(1 + F(c * c))).toBe(1);
    const r = f(0.5 * 1 * (1 + 1), 4);
    return {
      zero: [`it gives ${r}.`, '1.0 + c*c rounds to 1.0'],
      one: [`Right: ${r}, where`],
      nan: [`R comes out ${r}`],
    };
  },
  'pow-above-one': (p) => ({
    undefined: ['GLSL ES 3.00 (§8.2)', 'pow(0, 5) = 0'],
    r0: [`(R0 = ${f(r0(p.nT), 4)})`],
    one: [],
  }),
};

describe('the numbers in choice explanations are computed again here', () => {
  for (const q of QUESTIONS.filter((x) => x.kind === 'choice')) {
    it(`${q.id}: each phrase with its number, and no other number`, () => {
      expect(PHRASES[q.id], `${q.id} has its phrases here`).toBeTypeOf('function');
      for (const p of allParams(q, 'why')) {
        const expected = PHRASES[q.id](p);
        const options = q.options(p);
        expect(options.map((o) => o.id).sort()).toEqual(Object.keys(expected).sort());
        for (const o of options) {
          const why = o.why(p);
          for (const phrase of expected[o.id]) expect(why, `${q.id} ${JSON.stringify(p)} ${o.id}`).toContain(phrase);
          expect(unaccounted(why, expected[o.id]), `${q.id} ${JSON.stringify(p)} ${o.id}: ${why}`).toEqual([]);
        }
      }
    });
  }
  it('the figures a review recomputed: ×1.3 at n = 1.5 and ×2.5 at n = 1.33; 12.1 codes at 81° for n = 1.30; F(85°) 0.583, 1.165', () => {
    const growth = (n) => f((R(85, 1, n) * Math.sin(5 * DEG)) / r0(n), 1);
    expect([growth(1.5), growth(1.33)]).toEqual(['1.3', '2.5']);
    expect(PHRASES['schlick-visible']().visible[0]).toBe('12.1 codes (4.7 % of the range) at worst, near θ = 81° for n = 1.30, '
      + 'the lowest index of the range');
    expect(PHRASES['rim-scaling']({ nT: 1.33 })['scale-up'][0]).toBe('F at 85° is already 0.583; doubled it is 1.165');
  });
  it('an explanation with a number the phrases do not account for is caught', () => {
    expect(unaccounted('Right: 0.042 for glass, 1.5 and float32, R(0°) = 1', ['0.042 for glass'])).toEqual(['1.5']);
  });
});
