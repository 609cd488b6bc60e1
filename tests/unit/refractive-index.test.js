import { describe, expect, it } from 'vitest';
import { SORT_KEYS, customRow, materialRows, sortMaterialRows } from '../../src/panels/refractive-index/materialRows.js';
import { SPEED_OF_LIGHT_KM_S } from '../../src/optics/waves.js';
import { COLUMNS, formatIndex, formatKmS } from '../../src/panels/refractive-index/buildIndexTable.js';
import { setNumberLocale } from '../../src/ui/format.js';

const rows = materialRows();
const byId = (id) => rows.find((r) => r.id === id);

describe('material rows (refractive-index panel)', () => {
  it('every column of the table is a sort key of the rows, and the other way round', () => {
    expect(COLUMNS.map((c) => c.key)).toEqual(SORT_KEYS);
  });
  it('crown glass N-BK7 reflects 0.042 head-on from air', () => {
    expect(byId('glass').n).toBe(1.5167);
    expect(byId('glass').r0.toFixed(3)).toBe('0.042');
  });
  it('water: critical angle 48.6°, speed 0.75 c', () => {
    const water = byId('water');
    expect(water.critical.toFixed(1)).toBe('48.6');
    expect(water.critical).toBeCloseTo((Math.asin(1 / 1.3333) * 180) / Math.PI, 12);
    expect(water.speed).toBeCloseTo(1 / 1.3333, 15);
    expect(water.speedKmS).toBeCloseTo(SPEED_OF_LIGHT_KM_S / 1.3333, 9);
    expect(formatKmS(water.speedKmS)).toBe('224\u202f850');
  });
  it('sorting by n puts diamond last ascending and first descending', () => {
    expect(sortMaterialRows(rows, 'n', 'asc').at(-1).id).toBe('diamond');
    expect(sortMaterialRows(rows, 'n', 'desc')[0].id).toBe('diamond');
    expect(sortMaterialRows(rows, 'speed', 'asc')[0].id).toBe('diamond');
    expect(sortMaterialRows(rows, 'name', 'asc').slice(0, 2).map((r) => r.id)).toEqual(['acrylic', 'air']);
    expect(rows[0].id).toBe('air'); // the input is not reordered
  });
  it('a missing critical angle sorts last both ways; ties keep the data order', () => {
    const withVacuum = [customRow(1), ...rows];
    expect(withVacuum[0].critical).toBeNull();
    expect(sortMaterialRows(withVacuum, 'critical', 'asc').at(-1).id).toBe('custom');
    expect(sortMaterialRows(withVacuum, 'critical', 'desc').at(-1).id).toBe('custom');
    const coat = sortMaterialRows(rows, 'r0', 'asc').map((r) => r.id);
    expect(coat.indexOf('clear-coat')).toBeGreaterThan(coat.indexOf('acrylic'));
    expect(() => sortMaterialRows(rows, 'colour')).toThrow(RangeError);
  });
  it('the custom row follows its n', () => {
    const row = customRow(2);
    expect(row.r0).toBeCloseTo(1 / 9, 15);
    expect(row.critical).toBeCloseTo(30, 12);
  });
  it('indices keep the digits the data has, with the language\'s decimal sign', () => {
    expect(formatIndex(1.000293)).toBe('1.000293');
    expect(formatIndex(1.4)).toBe('1.4000');
    expect(formatIndex(1.3333)).toBe('1.3333');
    try {
      setNumberLocale('es');
      expect([1.000293, 1.4, 1.3333].map(formatIndex)).toEqual(['1,000293', '1,4000', '1,3333']);
    } finally {
      setNumberLocale('en');
    }
  });
});

describe('phase and group speed', async () => {
  const { groupIndex } = await import('../../src/optics/materials.js');
  it('a pulse in water travels at about 222 000 km/s, slower than the phase speed c/n', () => {
    const water = byId('water');
    expect(formatKmS(water.groupSpeedKmS, 1000)).toBe('222\u202f000');
    expect(water.groupSpeedKmS).toBeLessThan(water.speedKmS);
    // n_g = n − λ dn/dλ: with a straight line through (550, a), (650, c) the slope is (c − a)/100.
    const n589 = 1.3 - 39 * 1e-4; // on the line, 39 nm past 550
    expect(groupIndex({ 550: 1.3, 589: n589, 650: 1.29 })).toBeCloseTo(n589 + 589 * 1e-4, 12);
  });
  it('no group speed where the data has no dispersion: one wavelength, or the same n at all (air)', () => {
    expect(byId('air').groupSpeedKmS).toBeNull();
    expect(byId('skin').groupSpeedKmS).toBeNull();
    expect(customRow(1.7).groupSpeedKmS).toBeNull();
    expect(byId('air').source).toContain('0 °C');
  });
});
