// How a panel fits its frame on a slide (fit=1, src/host/fitLayout.js): the zoom floor from the
// root type, the zooms tried, the largest that fits, the layouts tried and which one shows a panel best.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import {
  GOOD_ZOOM, MAX_COLUMNS, NEAR_FIT, betterLayout, largestFitting, layoutCandidates, scrollingLayout, zoomFloor, zoomSteps,
} from '../../src/host/fitLayout.js';

describe('zoomFloor and zoomSteps', () => {
  it('keeps the root type at 12 px or more: 0.6 of the 20 px root, 0.5 of projector mode\'s 24 px', () => {
    expect(zoomFloor(20)).toBe(0.6);
    expect(zoomFloor(24)).toBe(0.5);
    expect(zoomFloor(13)).toBe(0.925); // 12/13 = 0.923, rounded up to a step
    expect(zoomFloor(10)).toBe(1); // type already small is not shrunk
    expect(zoomFloor(0)).toBe(1);
    expect(zoomFloor(Number.NaN)).toBe(1);
  });
  it('tries 1 down to the floor in steps of 0.025', () => {
    expect(zoomSteps(0.9)).toEqual([1, 0.975, 0.95, 0.925, 0.9]);
    expect(zoomSteps(0.6)).toHaveLength(17);
    expect(zoomSteps(1)).toEqual([1]);
  });
});

describe('largestFitting', () => {
  it('finds the largest zoom that fits, or null when even the smallest does not', () => {
    const steps = zoomSteps(0.6);
    expect(largestFitting(steps, (z) => z <= 0.71)).toBe(0.7);
    expect(largestFitting(steps, () => true)).toBe(1);
    expect(largestFitting(steps, () => false)).toBeNull();
    expect(largestFitting([], () => true)).toBeNull();
  });
  it('agrees with a scan from the top for any threshold, in few tries', () => {
    fc.assert(fc.property(fc.double({ min: 0, max: 1.2, noNaN: true }), (limit) => {
      const steps = zoomSteps(0.6);
      let tries = 0;
      const found = largestFitting(steps, (z) => { tries += 1; return z <= limit; });
      expect(found).toBe(steps.find((z) => z <= limit) ?? null);
      expect(tries).toBeLessThanOrEqual(7); // 17 steps: two ends and four halvings
    }));
  });
});

describe('layoutCandidates', () => {
  it('tries each number of columns uncapped, then each cap below the picture\'s own share', () => {
    expect(layoutCandidates({ columns: 2, pictureShare: 0.55 })).toEqual([
      { columns: 1, share: null }, { columns: 2, share: null },
      { columns: 1, share: 0.5 }, { columns: 2, share: 0.5 },
      { columns: 1, share: 0.4 }, { columns: 2, share: 0.4 },
      { columns: 1, share: 0.3 }, { columns: 2, share: 0.3 },
    ]);
  });
  it('caps nothing on a panel without a picture, and no more than MAX_COLUMNS columns', () => {
    expect(layoutCandidates({ columns: 9, pictureShare: null }).map((c) => c.columns)).toEqual([1, 2, 3]);
    expect(MAX_COLUMNS).toBe(3);
    expect(layoutCandidates({ columns: 0, pictureShare: 0.2 })).toEqual([{ columns: 1, share: null }]);
  });
});

describe('betterLayout', () => {
  const layout = (zoom, picture, columns = 1) => ({ zoom, picture, columns, share: null });
  it('serves the worse served of type and picture first', () => {
    // type 0.6/0.8 = 0.75 of enough against a picture at 0.3/0.5 = 0.6: the first is better
    expect(betterLayout(layout(0.6, 0.5), layout(0.8, 0.3))).toBe(true);
    expect(betterLayout(layout(0.8, 0.3), layout(0.6, 0.5))).toBe(false);
  });
  it('counts type and picture only up to enough, then prefers larger type, a larger picture, fewer columns', () => {
    expect(betterLayout(layout(1, 0.5), layout(GOOD_ZOOM, 0.9))).toBe(true);
    expect(betterLayout(layout(0.9, 0.6), layout(0.9, 0.5))).toBe(true);
    expect(betterLayout(layout(0.9, 0.5, 1), layout(0.9, 0.5, 2))).toBe(true);
    expect(betterLayout(layout(0.9, 0.5, 2), layout(0.9, 0.5, 1))).toBe(false);
    expect(betterLayout(layout(0.9, 0.5), layout(0.9, 0.5))).toBe(false);
  });
  it('judges a panel without a picture by its type alone', () => {
    expect(betterLayout(layout(0.7, null), layout(0.65, null, 1))).toBe(true);
  });
});

describe('scrollingLayout', () => {
  const least = (over) => ({ layout: { zoom: 0.6, columns: 2, share: 0.3 }, over });
  it('takes the layout that overflows least when it nearly fits', () => {
    expect(scrollingLayout({ least: least(40), frame: 600, floor: 0.6, pictureShare: 0.7 })).toEqual(least(40).layout);
    expect(scrollingLayout({ least: least(NEAR_FIT * 600), frame: 600, floor: 0.6, pictureShare: 0.7 }).columns).toBe(2);
  });
  it('else reads from the top in one column with type at GOOD_ZOOM and the picture on at most 60 % of the frame', () => {
    expect(scrollingLayout({ least: least(500), frame: 600, floor: 0.6, pictureShare: 0.7 })).toEqual({ zoom: GOOD_ZOOM, columns: 1, share: 0.6 });
    expect(scrollingLayout({ least: null, frame: 600, floor: 0.6, pictureShare: 0.4 })).toEqual({ zoom: GOOD_ZOOM, columns: 1, share: null });
    expect(scrollingLayout({ least: null, frame: 600, floor: 0.9, pictureShare: null })).toEqual({ zoom: 0.9, columns: 1, share: null });
  });
});
