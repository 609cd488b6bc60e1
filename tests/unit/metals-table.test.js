// What the metals panel's table reads (src/panels/metals/metalTableRow.js): a dip below F0 too
// small for four decimals keeps two significant digits, and no dip ever reads "−0.0000".
import { describe, expect, it } from 'vitest';
import { belowF0, metalTableRow } from '../../src/panels/metals/metalTableRow.js';
import { metalCurves, metalCurveStats } from '../../src/panels/metals/physics.js';
import { metalById } from '../../src/optics/materials.js';
import { conductorR, cosOfDegrees } from './oracle/fresnelOracle.js';

describe('how far below F0', () => {
  it('four decimals where they show the dip, two significant digits where they would read 0.0000', () => {
    expect(belowF0(0.0102)).toBe('0.0102 below F0');
    expect(belowF0(0.00145)).toBe('0.0014 below F0');
    expect(belowF0(1.19e-5)).toBe('0.000012 below F0');
    expect(belowF0(4e-5)).toBe('0.000040 below F0');
    expect(belowF0(1e-9)).toBe('1.0e−9 below F0');
  });

  it('no dip, or rounding a hair below none, reads 0.0000 and never carries a minus sign', () => {
    for (const dip of [0, -0, -1e-17, -4e-5]) {
      expect(belowF0(dip), String(dip)).toBe('0.0000 below F0');
    }
    for (const dip of [-1e-17, 1e-17, 1.19e-5, 4.9e-5, 0.3]) expect(belowF0(dip), String(dip)).not.toMatch(/^[−-]/);
  });
});

describe("copper's table", () => {
  const copper = metalById('copper');
  const stats = metalCurveStats(metalCurves(copper), copper);

  it("blue dips 1.2e−5 below F0 near 24.5° (a 50-digit oracle), and its row says so instead of (−0.0000)", () => {
    const f0 = conductorR(1, copper.n[2], copper.k[2]);
    const dip = f0.minus(conductorR(cosOfDegrees(24.53), copper.n[2], copper.k[2])).toNumber();
    expect(dip.toPrecision(2)).toBe('0.000012');
    expect(f0.toNumber().toFixed(4)).toBe('0.5383');
    const blue = metalTableRow(copper, stats[2], 2);
    expect(blue[0]).toBe('Blue 450 nm');
    expect(blue[4]).toBe('0.5383 at 24.53° (0.000012 below F0)');
    for (const cell of blue) expect(cell).not.toMatch(/[−-]0\.0000|\(0\.0000[ )]/);
  });

  it('red and green dip far enough for four decimals', () => {
    expect(metalTableRow(copper, stats[0], 0)[4]).toBe('0.9250 at 70.42° (0.0102 below F0)');
    expect(metalTableRow(copper, stats[1], 1)[4]).toBe('0.6219 at 48.16° (0.0014 below F0)');
  });
});
