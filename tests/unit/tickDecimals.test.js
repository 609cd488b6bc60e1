import { describe, it, expect } from 'vitest';
import { tickDecimals, tickLabel } from '../../src/ui/format.js';

describe('tickDecimals', () => {
  it('gives as many decimals as the tick step has', () => {
    expect(tickDecimals(10)).toBe(0);
    expect(tickDecimals(1)).toBe(0);
    expect(tickDecimals(0.2)).toBe(1);
    expect(tickDecimals(0.25)).toBe(2);
    expect(tickDecimals(0.0002)).toBe(4);
    expect(tickDecimals(1.5e-7)).toBe(8);
  });

  it('tells apart the ticks of a range from 0 to 0.001', () => {
    const ticks = [0, 0.0002, 0.0004, 0.0006, 0.0008, 0.001];
    const labels = ticks.map((t) => String(+t.toFixed(tickDecimals(0.0002))));
    expect(new Set(labels).size).toBe(ticks.length);
    expect(labels).toEqual(['0', '0.0002', '0.0004', '0.0006', '0.0008', '0.001']);
  });

  it('reads a step with rounding noise as the step it means', () => {
    expect(tickDecimals(0.1 + 0.2 - 0.2)).toBe(1);
    expect(tickDecimals(0)).toBe(0);
  });
});

describe('tickLabel', () => {
  it('drops the zeros a step does not need and writes a real minus sign', () => {
    expect([0, 0.5, 1, 1.5].map((t) => tickLabel(t, 0.5))).toEqual(['0', '0.5', '1', '1.5']);
    expect(tickLabel(-0.0004, 0.0002)).toBe('\u22120.0004');
    expect(tickLabel(0.1 + 0.2, 0.1)).toBe('0.3');
    expect(tickLabel(-1e-9, 0.25)).toBe('0');
  });
});
