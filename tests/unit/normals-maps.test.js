import { describe, expect, it } from 'vitest';
import { bumpCellMean, createBumps } from '../../src/normals/createBumps.js';
import { createGrooves } from '../../src/normals/createGrooves.js';
import { createMixedMap, MIXED_REGIONS } from '../../src/normals/createMixedMap.js';
import { createNormalMap, MAP_KINDS } from '../../src/normals/createNormalMap.js';
import { createValueNoise, valueNoiseHeight } from '../../src/normals/createValueNoise.js';
import { checkSize, sampleLevel0, sampleSlopes } from '../../src/normals/sampleLevel0.js';

const deg = (d) => (d * Math.PI) / 180;

describe('procedural maps: exact, unit, tileable', () => {
  it.each(MAP_KINDS)('%s: unit normals facing up, normal = normalize(b, 1), period 1 in u and v', (kind) => {
    const map = createNormalMap(kind);
    const n = [0, 0, 0];
    const b = [0, 0];
    for (let k = 0; k < 400; k++) {
      const u = (k * 0.6180339887) % 1;
      const v = (k * 0.7548776662) % 1;
      map.normalAt(u, v, n);
      map.slopeAt(u, v, b);
      expect(Math.hypot(...n)).toBeCloseTo(1, 14);
      expect(n[2]).toBeGreaterThan(0.08); // θ ≤ 85°
      expect(n[0] / n[2]).toBeCloseTo(b[0], 12);
      expect(n[1] / n[2]).toBeCloseTo(b[1], 12);
      const shifted = map.normalAt(u + 1, v - 2, [0, 0, 0]);
      for (let c = 0; c < 3; c++) expect(shifted[c]).toBeCloseTo(n[c], 12);
    }
  });

  it('V-grooves: the facets are exactly ±θ, the crease at t = ½', () => {
    const map = createGrooves({ frequency: 4, angleDeg: 30 });
    const a = map.normalAt(0.05, 0.3);
    const b = map.normalAt(0.2, 0.9);
    expect(a[0]).toBeCloseTo(Math.sin(deg(30)), 15);
    expect(b[0]).toBeCloseTo(-Math.sin(deg(30)), 15);
    expect(a[1]).toBe(0);
    expect(a[2]).toBeCloseTo(Math.cos(deg(30)), 15);
    const diag = createGrooves({ frequency: 2, angleDeg: 20, direction: 'diagonal' }).slopeAt(0.1, 0.05);
    expect(Math.hypot(...diag)).toBeCloseTo(Math.tan(deg(20)), 15);
    expect(diag[0]).toBeCloseTo(diag[1], 15);
  });

  it('bumps: flat at the cap centre and off the cap, tilted θm at the rim', () => {
    const map = createBumps({ frequency: 4, edgeAngleDeg: 45, fill: 0.8 });
    expect(map.normalAt(0.125, 0.125)).toEqual([0, 0, 1]);
    expect(map.normalAt(0.01, 0.01)).toEqual([0, 0, 1]); // a cell corner
    const rim = map.normalAt(0.125 + 0.1 * (1 - 1e-12), 0.125); // base radius 0.8 · ½ · ¼ = 0.1
    expect(Math.acos(rim[2])).toBeCloseTo(deg(45), 5);
    expect(() => createBumps({ edgeAngleDeg: 90 })).toThrow(RangeError); // log-divergent moments
  });

  it('bumpCellMean: a hemisphere-like cap lowers the cell mean below 1 by a known amount', () => {
    const { nz, slopeVariance } = bumpCellMean({ frequency: 8 });
    expect(nz).toBeCloseTo(0.9305978514896761, 14);
    expect(slopeVariance).toBeCloseTo(0.19417272432278568, 14);
    // independent of frequency (the whole pattern scales)
    expect(bumpCellMean({ frequency: 2 }).nz).toBeCloseTo(nz, 14);
  });

  it('value noise: the slope is −∇h (central differences), and the tile seam is continuous', () => {
    const params = { frequency: 4, octaves: 3, seed: 7 };
    const map = createValueNoise(params);
    const h = 1e-6;
    for (const [u, v] of [[0.1, 0.2], [0.77, 0.31], [0.5, 0.99]]) {
      const gx = (valueNoiseHeight(params, u + h, v) - valueNoiseHeight(params, u - h, v)) / (2 * h);
      const gy = (valueNoiseHeight(params, u, v + h) - valueNoiseHeight(params, u, v - h)) / (2 * h);
      const b = map.slopeAt(u, v);
      expect(b[0]).toBeCloseTo(-gx, 6);
      expect(b[1]).toBeCloseTo(-gy, 6);
    }
    const left = map.slopeAt(1 - 1e-9, 0.4);
    const right = map.slopeAt(0, 0.4);
    expect(left[0]).toBeCloseTo(right[0], 6);
    expect(left[1]).toBeCloseTo(right[1], 6);
  });

  it('mixed map: every region kind appears, and flat regions are flat', () => {
    const map = createMixedMap();
    const seen = new Set();
    for (let j = 0; j < 4; j++) for (let i = 0; i < 4; i++) seen.add(map.regionAt((i + 0.5) / 4, (j + 0.5) / 4));
    expect([...seen].sort()).toEqual([...MIXED_REGIONS].sort());
    expect(map.regionAt(0.1, 0.1)).toBe('flat');
    expect(map.normalAt(0.1, 0.1)).toEqual([0, 0, 1]);
    expect(map.regionAt(0.3, 0.1)).toBe('bumps');
  });

  it('rejects what cannot tile and unknown kinds', () => {
    expect(() => createGrooves({ frequency: 2.5 })).toThrow(RangeError);
    expect(() => createNormalMap('checker', { frequency: 7 })).toThrow(RangeError); // odd: parity flips at the seam
    expect(() => createNormalMap('sand')).toThrow(RangeError);
  });
});

describe('sampleLevel0', () => {
  it('is row-major with texel centres, row 0 at v ≈ 0; 4 components put alpha = 1', () => {
    const map = createNormalMap('noise', { frequency: 4 });
    const size = 64;
    const d3 = sampleLevel0(map, size);
    const d4 = sampleLevel0(map, size, { components: 4 });
    expect(d3.length).toBe(size * size * 3);
    const [i, j] = [5, 17];
    const n = map.normalAt((i + 0.5) / size, (j + 0.5) / size);
    for (let c = 0; c < 3; c++) {
      expect(d3[(j * size + i) * 3 + c]).toBe(Math.fround(n[c]));
      expect(d4[(j * size + i) * 4 + c]).toBe(Math.fround(n[c]));
    }
    expect(d4[(j * size + i) * 4 + 3]).toBe(1);
    const s = sampleSlopes(map, size);
    expect(s[2 * (j * size + i)]).toBeCloseTo(n[0] / n[2], 6);
  });

  it('accepts powers of two only', () => {
    expect(checkSize(1024)).toBe(1024);
    for (const bad of [0, 100, 8192, 64.5]) expect(() => checkSize(bad)).toThrow(RangeError);
  });
});
