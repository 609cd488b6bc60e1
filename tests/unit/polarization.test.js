import { describe, expect, it } from 'vitest';
import { brewsterAngle, fresnelExact, fresnelPolarized } from '../../src/optics/fresnel.js';
import { reflectanceCurves } from '../../src/optics/curves.js';

// The polarization panel's note claims an Rs-only reading is never below the unpolarized value.
describe('what the polarization panel states', () => {
  const pairs = [[1, 1.5], [1.5, 1], [1, 2.4166], [1.3333, 1], [1, 1.0003]];
  it('Rs ≥ mean ≥ Rp at every sampled angle, and the mean is fresnelExact', () => {
    for (const [a, b] of pairs) {
      const { s, p, exact } = reflectanceCurves(a, b);
      s.forEach((rs, i) => {
        expect(rs).toBeGreaterThanOrEqual(exact[i] - 1e-15);
        expect(exact[i]).toBeGreaterThanOrEqual(p[i] - 1e-15);
        expect(0.5 * (rs + p[i])).toBeCloseTo(exact[i], 12);
      });
    }
  });
  it('air to glass: Brewster 56.31° with Rp = 0.0000; at 60° Rs > mean > Rp', () => {
    const b = brewsterAngle(1, 1.5);
    expect(((b * 180) / Math.PI).toFixed(2)).toBe('56.31');
    expect(fresnelPolarized(Math.cos(b), 1, 1.5).p.toFixed(4)).toBe('0.0000');
    const c = Math.cos(Math.PI / 3);
    const { s, p } = fresnelPolarized(c, 1, 1.5);
    const mean = fresnelExact(c, 1, 1.5);
    expect(s).toBeGreaterThan(mean);
    expect(mean).toBeGreaterThan(p);
    expect((s / mean).toFixed(2)).toBe('1.98');
  });
});
