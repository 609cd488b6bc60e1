import { describe, expect, it } from 'vitest';
import { bandedRmse, toneMap } from '../../src/normals/bandedRmse.js';

const px = (...values) => new Float32Array(values);

describe('toneMap', () => {
  it('is 1 − e^−x, 0 for negatives', () => {
    expect(toneMap(0)).toBe(0);
    expect(toneMap(-3)).toBe(0);
    expect(toneMap(1)).toBeCloseTo(1 - Math.exp(-1), 15);
  });
});

describe('bandedRmse', () => {
  it('is 0 for identical images and skips pixels with negative λ', () => {
    const a = px(1, 2, 3, 0, 9, 9, 9, -1);
    const b = px(1, 2, 3, 0, 0, 0, 0, -1);
    const r = bandedRmse(a, b, { bands: 2 });
    expect(r.rmse).toBe(0);
    expect(r.count).toBe(1);
    expect(r.bands[1].count).toBe(0);
    expect(r.bands[1].rmse).toBeNaN();
  });

  it('averages squared tone-mapped differences per band', () => {
    const d = toneMap(1);
    // pixel 0: λ = 0.5, one channel off by toneMap(1); pixel 1: λ = 3.2 (clamped into band 1), all channels off
    const a = px(1, 0, 0, 0.5, 1, 1, 1, 3.2);
    const b = px(0, 0, 0, 0, 0, 0, 0, 0);
    const r = bandedRmse(a, b, { bands: 2 });
    expect(r.bands[0].rmse).toBeCloseTo(Math.sqrt((d * d) / 3), 12);
    expect(r.bands[1].rmse).toBeCloseTo(d, 12);
    expect(r.rmse).toBeCloseTo(Math.sqrt((4 * d * d) / 6), 12);
    expect(r.bands[1].count).toBe(1);
  });

  it('rejects mismatched sizes', () => {
    expect(() => bandedRmse(px(0, 0, 0, 0), px(0, 0, 0))).toThrow(RangeError);
    expect(() => bandedRmse(px(0, 0, 0, 0), px(0, 0, 0, 0), { bands: 0 })).toThrow(RangeError);
  });
});
