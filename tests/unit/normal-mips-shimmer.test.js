import { describe, expect, it } from 'vitest';
import { meanBrightnessChange } from '../../src/normals/shimmer.js';
import { toneMap } from '../../src/normals/bandedRmse.js';

describe('meanBrightnessChange', () => {
  it('is 0 for a still picture', () => {
    const a = new Float32Array([1, 2, 3, 0.5, 0, 0, 0, 1]);
    expect(meanBrightnessChange(a, a)).toBe(0);
  });
  it('averages |Δ luminance| of tone-mapped colours over surface pixels only', () => {
    const a = new Float32Array([1, 1, 1, 0, 5, 5, 5, -1, 0, 0, 0, 2]);
    const b = new Float32Array([0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 2]);
    // luminance weights sum to 1, so a grey of 1 has brightness toneMap(1)
    expect(meanBrightnessChange(a, b)).toBeCloseTo(toneMap(1) / 2, 12);
  });
  it('is NaN without surface and rejects mismatched sizes', () => {
    const sky = new Float32Array([1, 1, 1, -1]);
    expect(meanBrightnessChange(sky, sky)).toBeNaN();
    expect(() => meanBrightnessChange(sky, new Float32Array(8))).toThrow(RangeError);
  });
});
