import { describe, expect, it } from 'vitest';
import { maxSpread, r0Steps } from '../../src/panels/r0-derivation/physics.js';
import { fresnelExact, normalIncidence } from '../../src/optics/fresnel.js';

const pairs = [[1, 1.5], [1.5, 1], [1.333, 1], [1, 2.417], [1.31, 1.333], [2, 2], [3, 1]];

describe('r0Steps', () => {
  it('every line of the derivation has the value of normalIncidence and fresnelExact(1, …)', () => {
    for (const [a, b] of pairs) {
      const { lines } = r0Steps(a, b);
      expect(lines).toHaveLength(9);
      for (const line of lines) {
        expect(line.value).toBeCloseTo(normalIncidence(a, b), 15);
        expect(line.value).toBeCloseTo(fresnelExact(1, a, b), 15);
      }
      expect(maxSpread(lines.map((l) => l.value))).toBeLessThan(1e-15);
      expect(lines.at(-1).value).toBe(normalIncidence(a, b)); // the same expression
    }
  });
  it('θ = 0 gives c = n_i/n_t and g = 1', () => {
    const { setup } = r0Steps(1, 1.5);
    expect(setup.map((s) => s.symbol)).toEqual(['c', 'g']);
    expect(setup[0].value).toBe(1 / 1.5);
    expect(setup[1].value).toBeCloseTo(1, 15);
  });
  it('the lecture values: 0.04 for air to glass, 0.020373 for water to air', () => {
    expect(r0Steps(1, 1.5).lines.map((l) => l.value.toFixed(6))).toEqual(Array(9).fill('0.040000'));
    expect(r0Steps(1.333, 1).lines.map((l) => l.value.toFixed(6))).toEqual(Array(9).fill('0.020373'));
  });
  it('each line is typeset from its own TeX, and bad indices throw', () => {
    const { lines } = r0Steps(1, 1.5);
    expect(new Set(lines.map((l) => l.tex)).size).toBe(lines.length);
    expect(lines.at(-1).tex).toContain('n_t-n_i');
    expect(() => r0Steps(0, 1.5)).toThrow(RangeError);
    expect(() => r0Steps(1, Number.NaN)).toThrow(RangeError);
  });
  it('maxSpread is the largest pairwise difference', () => {
    expect(maxSpread([0.1, 0.4, 0.25])).toBeCloseTo(0.3, 15);
    expect(maxSpread([2, 2])).toBe(0);
  });
});
