// The zoom that makes an embed fit its frame (fit=1, src/host/fitToFrame.js): smaller in proportion
// while the content overflows, never below MIN_ZOOM, unchanged once it fits.
import { describe, expect, it } from 'vitest';
import { MIN_ZOOM, shrunkZoom } from '../../src/host/fitToFrame.js';

describe('shrunkZoom', () => {
  it('shrinks in proportion while the content overflows, and leaves a fitting zoom alone', () => {
    expect(shrunkZoom(1000, 600, 1)).toBe(0.6);
    expect(shrunkZoom(700, 600, 0.6)).toBeCloseTo(0.514, 3);
    expect(shrunkZoom(600, 600, 0.7)).toBe(0.7);
    expect(shrunkZoom(601, 600, 0.7)).toBe(0.7); // a pixel of rounding is no overflow
    expect(shrunkZoom(300, 600, 0.5)).toBe(0.5);
  });
  it('stops at MIN_ZOOM, and ignores a frame with no height', () => {
    expect(shrunkZoom(10_000, 600, 1)).toBe(MIN_ZOOM);
    expect(shrunkZoom(800, 0, 1)).toBe(1);
  });
});
