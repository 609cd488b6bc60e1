import { describe, it, expect } from 'vitest';
import { quietestSpot } from '../../src/ui/quietestSpot.js';

/** Boxes 100 px wide and 12 high at x0, one per top. */
const column = (x0, tops) => tops.map((y0) => ({ x0, x1: x0 + 100, y0, y1: y0 + 12 }));
const along = (y, from = 90, to = 240) => Array.from({ length: Math.floor((to - from) / 3) }, (_, i) => [from + i * 3, y]);
const right = column(100, [0, 10, 20, 30, 40, 50]);

describe('quietestSpot', () => {
  it('keeps the first place when nothing is under it', () => {
    expect(quietestSpot(right, along(45), [])).toBe(right[0]);
  });

  it('moves off a curve that runs along the top', () => {
    const spot = quietestSpot(right, [...along(5), ...along(45)], []);
    expect(spot.y0).toBeGreaterThan(5);
    expect(spot.y1).toBeLessThan(45);
  });

  it('ignores samples outside the box’s width', () => {
    const beside = Array.from({ length: 20 }, (_, i) => [300 + i, 5]);
    expect(quietestSpot(right, beside, [])).toBe(right[0]);
  });

  it('never sits on a label already placed, even where that covers more samples', () => {
    const spots = column(100, [0, 20]);
    expect(quietestSpot(spots, along(25), [{ x0: 150, x1: 250, y0: 0, y1: 14 }])).toBe(spots[1]);
  });

  it('takes the box covering fewest samples when every box covers some', () => {
    const spots = column(100, [0, 10, 20]);
    const points = [...along(4), ...along(16), [150, 25], [160, 25]];
    // 0–12 covers the curve at 4, 10–22 the one at 16, 20–32 only the two samples at 25.
    expect(quietestSpot(spots, points, [])).toBe(spots[2]);
  });

  it('goes to the other side of its line when that side is clear', () => {
    const left = column(0, [0, 10]);
    const spots = [...column(110, [0, 10]), ...left];
    const rising = Array.from({ length: 40 }, (_, i) => [110 + i * 2.5, 40 - i]); // a steep rise right of x = 110
    expect(quietestSpot(spots, [...rising, ...along(4, 110, 210)], [])).toBe(left[0]);
  });
});
