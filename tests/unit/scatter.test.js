import { describe, it, expect } from 'vitest';
import { costTickLabel, linearTicks, powerLabel } from '../../src/panels/speed-accuracy/scatterAxes.js';
import { placeLabels } from '../../src/panels/speed-accuracy/scatterLabels.js';

const overlap = (a, b) => Math.max(0, Math.min(a.x1, b.x1) - Math.max(a.x0, b.x0)) * Math.max(0, Math.min(a.y1, b.y1) - Math.max(a.y0, b.y0));

describe('speed/accuracy scatter axes', () => {
  it('puts cost ticks on 1, 2 or 5 × 10^k and labels them with the digits the step needs', () => {
    const { ticks, step } = linearTicks(0, 51.84);
    expect(step).toBe(10);
    expect(ticks.map((t) => costTickLabel(t, step))).toEqual(['0', '10', '20', '30', '40', '50']);
    const small = linearTicks(0, 2.7);
    expect(small.step).toBe(0.5);
    expect(small.ticks.map((t) => costTickLabel(t, small.step))).toEqual(['0', '0.5', '1', '1.5', '2', '2.5']);
    // Rounding noise in the running sum (0.1 + 0.2) never shows.
    const tenths = linearTicks(0, 0.6);
    expect(tenths.ticks.map((t) => costTickLabel(t, tenths.step))).toEqual(['0', '0.1', '0.2', '0.3', '0.4', '0.5', '0.6']);
  });

  it('writes a negative cost (a timing below its baseline) with a minus sign', () => {
    const { ticks, step } = linearTicks(-30, 50);
    const labels = ticks.map((t) => costTickLabel(t, step));
    expect(labels[0]).toBe('\u221220');
    expect(labels.join(' ')).not.toContain('-');
  });

  it('writes very large or small costs as powers of ten', () => {
    expect(costTickLabel(20000, 10000)).toBe('2e4');
    expect(costTickLabel(0.0005, 0.0001)).toBe('5e\u22124');
  });

  it('labels the decades of the error axis in plain numbers from 0.01 to 1000', () => {
    expect([-6, -3, -2, -1, 0, 1, 3, 4].map(powerLabel)).toEqual(['1e\u22126', '1e\u22123', '0.01', '0.1', '1', '10', '1000', '1e4']);
  });
});

describe('speed/accuracy scatter labels', () => {
  const box = { left: 0, right: 400, top: 0, bottom: 300 };
  const lineH = 22;
  const pointRects = (drawn) => drawn.map(({ px, py }) => ({ x0: px - 9, x1: px + 9, y0: py - 9, y1: py + 9, weight: 50 }));

  it('puts a lone label to the right of its point, on its line', () => {
    const drawn = [{ px: 100, py: 150 }];
    const [{ spot, rect }] = placeLabels(drawn, [60], { box, s: 1, lineH }, pointRects(drawn));
    expect(spot).toEqual({ x: 116, y: 150 });
    expect(rect).toEqual({ x0: 113, x1: 179, y0: 139, y1: 161 });
  });

  it('moves crowded labels apart so that none covers another label or a point', () => {
    const drawn = [{ px: 100, py: 150 }, { px: 104, py: 152 }, { px: 108, py: 149 }];
    const taken = pointRects(drawn);
    const placed = placeLabels(drawn, [80, 80, 80], { box, s: 1, lineH }, taken);
    const rects = placed.map((p) => p.rect);
    for (const [i, r] of rects.entries()) {
      expect(r.x0 >= box.left && r.x1 <= box.right && r.y0 >= box.top && r.y1 <= box.bottom).toBe(true);
      for (const point of pointRects(drawn)) expect(overlap(r, point)).toBe(0);
      for (const other of rects.slice(i + 1)) expect(overlap(r, other)).toBe(0);
    }
    expect(taken).toHaveLength(drawn.length + placed.length);
  });

  it('keeps a label clear of a rectangle already taken (the budget label)', () => {
    const drawn = [{ px: 100, py: 150 }];
    const budget = { x0: 110, x1: 300, y0: 130, y1: 170 };
    const [{ rect }] = placeLabels(drawn, [60], { box, s: 1, lineH }, [budget, ...pointRects(drawn)]);
    expect(overlap(rect, budget)).toBe(0);
  });
});
