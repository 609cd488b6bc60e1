// The place scripts/measurePlaces.js suggests for a panel, from the heights it measured.
import { describe, expect, it } from 'vitest';
import { placeFromHeights, placeLine, placeProblems } from '../../scripts/placeFromHeights.js';

const now = { narrow: 970, wide: 610, widest: 710 };

describe('a place from mounted heights', () => {
  it('is 92 % of the smallest height per layout, rounded down to 10 px', () => {
    // 0.92 × 1000 = 920; 0.92 × 700 = 644 → 640; 0.92 × 799 = 735.08 → 730
    expect(placeFromHeights({ narrow: [1000, 1100], wide: [700], widest: [799] }, now)).toEqual({ narrow: 920, wide: 640, widest: 730 });
  });
  it('keeps the entry\'s value for a layout no width measured', () => {
    expect(placeFromHeights({ wide: [700] }, now)).toEqual({ narrow: 970, wide: 640, widest: 710 });
  });
  it('passes the browser tests\' bounds for any height it was made from', () => {
    for (let height = 50; height < 4000; height += 7) {
      const heights = { narrow: [height], wide: [height + 3], widest: [height * 2] };
      expect(placeProblems(placeFromHeights(heights, now), heights), String(height)).toEqual([]);
    }
  });
  it('names a place taller than the mounted panel, or no more than 40 % of it', () => {
    expect(placeProblems(now, { narrow: [960], wide: [1600], widest: [720] })).toEqual([
      'narrow 970 is taller than the mounted 960',
      'wide 610 is no more than 40 % of the mounted 1600',
    ]);
  });
  it('is written as the manifest writes it', () => {
    expect(placeLine(now)).toBe('place: { narrow: 970, wide: 610, widest: 710 },');
  });
});
