// What the fresnel-lighting panel says of its Fresnel sphere's rim (src/panels/fresnel-lighting/words.js),
// held against F from the textbook formulas (tests/unit/oracle): a turn toward ks is claimed only where
// the weights it shows differ, and a coat that reflects nothing is said to.
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
const say = (nT, method) => describeSpheres({ nT, method, weight: 0.04 }, 0);
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
      + 'n_t = 1 reflects nothing (the exact F at 80° is 0.0000): Schlick\'s (1 − cos θ)⁵ term does not vanish with R0');
    // An index a hair above 1: the coat reflects next to nothing, and Schlick's rim is as white.
    expect(fresnelR(80, 1, 1.0001)).toBeLessThan(0.00005);
    expect(say(1.0001, 'schlick')).toContain(`F is 0.0000 at 0° and ${schlick(80, 1.0001).toFixed(4)} at 80°, ${TURNS}, although a `
      + 'coat of n_t = 1.0001 reflects next to nothing (the exact F at 80° is 0.0000)');
  });
  it('near n_t = 1, claims a turn exactly where the F it shows at 80° differs from the F at 0°', () => {
    const indices = [1.00001, 1.0001, 1.0003, 1.0004, 1.0005, 1.001, 1.002, 1.01];
    const seen = new Set();
    for (const method of ['exact', 'layered']) {
      for (const n of indices) {
        const differs = weight(80, n, method).toFixed(4) !== weight(0, n, method).toFixed(4);
        seen.add(differs);
        expect(say(n, method).includes(TURNS), `${method} ${n}`).toBe(differs);
        if (!differs) expect(say(n, method)).toContain('to the decimals shown the coat reflects nothing up to 80°');
      }
    }
    expect([...seen].sort()).toEqual([false, true]); // both cases are among the indices
  });
});
