// What the fresnel-lighting panel says of its Fresnel sphere's rim (src/panels/fresnel-lighting/words.js),
// held against F from the textbook formulas (tests/unit/oracle) and the sRGB curve: a turn toward ks is
// claimed only where the rim's colour moves by a display code or more, a coat that reflects nothing is
// said to, and Schlick's rim is said to overstate a coat of an index near 1.
import { describe, expect, it } from 'vitest';
import { describeSpheres } from '../../src/panels/fresnel-lighting/words.js';
import { fresnelR } from './oracle/rightAnswers.js';

const DEG = Math.PI / 180;
// Schlick, Computer Graphics Forum 13(3), 1994: R0 + (1 − R0)(1 − cos θ)⁵.
const schlick = (thetaDeg, n) => {
  const r0 = ((n - 1) / (n + 1)) ** 2;
  return r0 + (1 - r0) * (1 - Math.cos(thetaDeg * DEG)) ** 5;
};
const weight = (thetaDeg, n, method) => (method === 'schlick' ? schlick(thetaDeg, n) : fresnelR(thetaDeg, 1, n));
const KD = '#a3241c'; // the panel's defaults
const KS = '#ffffff';
const say = (nT, method) => describeSpheres({ nT, method, weight: 0.04, kd: KD, ks: KS }, 0);
// IEC 61966-2-1 sRGB: a byte to linear and back, to count display codes.
const toLinear = (byte) => { const c = byte / 255; return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4; };
const toCode = (c) => 255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);
const bytes = (hex) => [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
/** The most codes by which mix(kd, ks, F) moves off kd in a channel. */
const codes = (F) => Math.max(...bytes(KD).map((b, i) => {
  const [d, s] = [toLinear(b), toLinear(bytes(KS)[i])];
  return Math.abs(toCode(d + (s - d) * F) - toCode(d));
}));
const TURNS = 'so its rim turns toward ks';

describe('the Fresnel sphere\'s rim, in words', () => {
  it('turns toward ks where F grows, with F at 0° and 80° as the formulas give them', () => {
    for (const method of ['exact', 'schlick', 'layered']) {
      for (const n of [1.33, 1.5, 2]) {
        expect(say(n, method)).toContain(`F is ${weight(0, n, method).toFixed(4)} at 0° and ${weight(80, n, method).toFixed(4)} at 80°, ${TURNS}`);
      }
    }
  });
  it('with n_t = 1: F = 0 at every angle and nothing turns (exact and layered)', () => {
    for (const method of ['exact', 'layered']) {
      for (const theta of [0, 40, 80, 89.9]) expect(fresnelR(theta, 1, 1)).toBeLessThan(1e-20);
      expect(say(1, method)).toContain('F = 0 at every angle, since with n_t = 1 the coat matches air and reflects nothing, so the '
        + 'sphere shows its base colour kd out to the rim and nothing turns toward ks');
      expect(say(1, method)).not.toContain(TURNS);
    }
  });
  it('with n_t = 1 and Schlick\'s form: the rim turns, and the words say that the coat itself reflects nothing', () => {
    expect(schlick(80, 1)).toBeCloseTo(0.3853, 4); // (1 − cos 80°)⁵
    expect(say(1, 'schlick')).toContain(`F is 0.0000 at 0° and ${schlick(80, 1).toFixed(4)} at 80°, ${TURNS}, although a coat of `
      + 'n_t = 1 reflects nothing (the exact F at 80°, 0.0000, would not move the rim\'s mix of the kd and ks colours by one display code): '
      + 'Schlick\'s (1 − cos θ)⁵ term does not vanish with R0');
    // The smallest index above 1 the control gives: the exact F moves the rim by under a code, Schlick's turns it.
    expect(codes(fresnelR(80, 1, 1.001))).toBeLessThan(1);
    expect(say(1.001, 'schlick')).toContain(`F is 0.0000 at 0° and ${schlick(80, 1.001).toFixed(4)} at 80°, ${TURNS}, although a `
      + `coat of n_t = 1.001 reflects next to nothing (the exact F at 80°, ${fresnelR(80, 1, 1.001).toFixed(4)}, would not`);
  });
  it('near n_t = 1, claims a turn exactly where F at 80° moves the rim\'s colour by a display code or more', () => {
    const indices = [1.00001, 1.0001, 1.0005, 1.001, 1.002, 1.003, 1.005, 1.01];
    const seen = new Set();
    for (const method of ['exact', 'layered']) {
      for (const n of indices) {
        const visible = codes(weight(80, n, method)) >= 1;
        seen.add(visible);
        expect(say(n, method).includes(TURNS), `${method} ${n}`).toBe(visible);
        if (!visible) expect(say(n, method)).toContain('too little to move the rim\'s mix of the kd and ks colours by one display code');
      }
    }
    expect([...seen].sort()).toEqual([false, true]); // both cases are among the indices
  });
  it('with kd and ks one colour: no claim that the rim turns, or that F is too small to turn it; the lighting named', () => {
    for (const method of ['exact', 'schlick', 'layered']) {
      const text = describeSpheres({ nT: 1.5, method, weight: 0.04, kd: '#ffffff', ks: '#ffffff' }, 0);
      expect(text).toContain(method === 'layered'
        ? 'but kd and ks are the same colour, so the weight moves the rim toward the coat\'s mirror image of its surroundings, away from '
          + 'the base lit by the sun and sky; that base differs from ks in colour too, unless it is grey'
        : 'but kd and ks are the same colour, so the weight moves the rim only through their lighting');
      expect(text).not.toContain(TURNS);
      expect(text).not.toContain('too little');
      expect(text).toContain(`and ${weight(80, 1.5, method === 'schlick' ? 'schlick' : 'exact').toFixed(4)} at 80°`);
    }
    // Two display codes apart is a colour of its own again.
    expect(describeSpheres({ nT: 1.5, method: 'exact', weight: 0.04, kd: '#fdfdfd', ks: '#ffffff' }, 0)).not.toContain('same colour');
  });
  it('says where Schlick\'s rim is far whiter than the exact F would make it, an index near 1, and not for glass', () => {
    for (const n of [1.01, 1.05, 1.1]) {
      expect(schlick(80, n) / fresnelR(80, 1, n), String(n)).toBeGreaterThan(1.5);
      expect(say(n, 'schlick'), String(n)).toContain(`${TURNS}, much more than the exact F at 80°, ${fresnelR(80, 1, n).toFixed(4)}, would turn it`);
    }
    for (const n of [1.33, 1.5, 2]) {
      expect(schlick(80, n) / fresnelR(80, 1, n), String(n)).toBeLessThan(1.5);
      expect(say(n, 'schlick'), String(n)).not.toContain('much more than the exact F');
    }
  });
});
