import { describe, expect, it } from 'vitest';
import { bumpCellMean } from '../../src/normals/createBumps.js';
import { createNormalMap } from '../../src/normals/createNormalMap.js';
import { footprintAverage, groundTruthLevel, texelFootprint } from '../../src/normals/footprintAverage.js';
import { buildMomentPyramid } from '../../src/normals/momentPyramid.js';
import { sampleLevel0 } from '../../src/normals/sampleLevel0.js';

describe('footprintAverage: the ground truth of a mip texel', () => {
  it('texelFootprint covers 2^level / size of the tile', () => {
    expect(texelFootprint(64, 0, 3, 5)).toEqual([3 / 64, 5 / 64, 4 / 64, 6 / 64]);
    expect(texelFootprint(64, 6, 0, 0)).toEqual([0, 0, 1, 1]);
  });

  it('converges to the exact cap integral: |error| ≤ 0.1/n (a crease at the rim), 2.2e-5 at n = 512', () => {
    const map = createNormalMap('bumps', { frequency: 4 });
    const exact = bumpCellMean({ frequency: 4 });
    const cell = [0, 0, 0.25, 0.25];
    const errors = [];
    for (const n of [8, 16, 32, 64, 128, 256, 512]) {
      const f = footprintAverage(map, cell, n);
      const nz = Math.abs(f.normal[2] - exact.nz);
      const m = Math.abs(f.moments[0] + f.moments[1] - exact.slopeVariance);
      expect(nz).toBeLessThanOrEqual(0.1 / n);
      expect(m).toBeLessThanOrEqual(0.35 / n);
      expect(Math.abs(f.normal[0])).toBeLessThan(1e-12); // symmetric cell
      expect(f.samples).toBe(n * n);
      errors.push(nz);
    }
    expect(errors.at(-1)).toBeLessThan(3e-5);
    expect(errors.at(-1)).toBeLessThan(errors[0] / 50);
  });

  it('a V-groove period averages to |N| = cos θ exactly for any even sample count', () => {
    const map = createNormalMap('grooves', { frequency: 4, angleDeg: 30 });
    for (const n of [2, 6, 64]) {
      const f = footprintAverage(map, [0, 0, 0.25, 0.25], n);
      expect(f.length).toBeCloseTo(Math.cos(Math.PI / 6), 12);
      expect(f.moments[0] - f.slope[0] ** 2).toBeCloseTo(1 / 3, 12); // tan²30°
      expect(f.moments[1]).toBe(0);
    }
  });

  it('with 2^level samples per axis it is exactly the box-filtered chain texel', () => {
    const size = 64;
    const map = createNormalMap('mixed', { blocks: 2 });
    const pyramid = buildMomentPyramid(sampleLevel0(map, size), size);
    for (const level of [1, 3, 6]) {
      const ls = size >> level;
      const truth = groundTruthLevel(map, size, level, 2 ** level);
      let worst = 0;
      for (let k = 0; k < truth.length; k++) worst = Math.max(worst, Math.abs(truth[k] - pyramid[level].data[k]));
      expect(worst).toBeLessThan(2e-6);
      const [i, j] = [ls - 1, ls >> 1];
      const f = footprintAverage(map, texelFootprint(size, level, i, j), 2 ** level);
      expect(truth[(j * ls + i) * 8 + 2]).toBeCloseTo(f.normal[2], 6);
      expect(truth[(j * ls + i) * 8 + 7]).toBeCloseTo(f.moments[2], 6);
    }
  });

  it('and more samples than level-0 texels reveal what point-sampled level 0 missed', () => {
    const size = 64;
    const map = createNormalMap('bumps', { frequency: 8 }); // 8 texels per cell
    const pyramid = buildMomentPyramid(sampleLevel0(map, size), size);
    const fine = footprintAverage(map, texelFootprint(size, 3, 0, 0), 256);
    const exact = bumpCellMean({ frequency: 8 }).nz;
    expect(Math.abs(fine.normal[2] - exact)).toBeLessThan(1e-3);
    expect(pyramid[3].data[2] - exact).toBeCloseTo(0.00234, 5); // 8×8 centres see the caps a bit too flat
  });
});
