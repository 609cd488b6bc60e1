import { describe, expect, it } from 'vitest';
import { bumpCellMean } from '../../src/normals/createBumps.js';
import { createNormalMap } from '../../src/normals/createNormalMap.js';
import { buildAllChains, buildChain } from '../../src/normals/buildChain.js';
import { effectiveRoughness, texelLobe } from '../../src/normals/effectiveRoughness.js';
import { toksvigAlpha, vmfAlpha } from '../../src/normals/lobeFormulas.js';
import { buildMomentPyramid, chainTexelCount, levelCount, levelSize } from '../../src/normals/momentPyramid.js';
import { sampleLevel0 } from '../../src/normals/sampleLevel0.js';
import { TECHNIQUES } from '../../src/normals/techniqueLayout.js';

const deg = (d) => (d * Math.PI) / 180;
const lengthAt = (d, o) => Math.hypot(d[o], d[o + 1], d[o + 2]);

function chainsOf(kind, params, size, opts) {
  return buildAllChains(sampleLevel0(createNormalMap(kind, params), size), size, opts);
}

describe('chain sizes and level counts', () => {
  it('log2(size) + 1 levels, (4·size² − 1)/3 texels', () => {
    for (let n = 0; n <= 10; n++) {
      const size = 2 ** n;
      expect(levelCount(size)).toBe(n + 1);
      expect(chainTexelCount(size)).toBe((4 * size * size - 1) / 3);
    }
    expect(chainTexelCount(1024)).toBe(1398101);
  });

  it('every technique has every level down to 1×1 with size² · components values', () => {
    const { chains } = chainsOf('noise', {}, 64);
    for (const technique of TECHNIQUES) {
      const chain = chains[technique];
      expect(chain.levels.map((l) => l.size)).toEqual([64, 32, 16, 8, 4, 2, 1]);
      for (const { size, data } of chain.levels) expect(data.length).toBe(size * size * chain.components);
    }
    expect(Object.fromEntries(TECHNIQUES.map((t) => [t, chains[t].components]))).toEqual({
      naive: 3, renormalized: 3, toksvig: 3, lean: 5, clean: 3, vmf: 4,
    });
    expect(levelSize(64, 9)).toBe(1);
  });

  it("Toksvig stores exactly naive's data (shared), and buildChain gives the same values", () => {
    const { pyramid, chains } = chainsOf('bumps', {}, 64, { precision: 'u8' });
    expect(chains.toksvig.levels[3].data).toBe(chains.naive.levels[3].data);
    expect(chains.toksvig.technique).toBe('toksvig');
    expect(buildChain(pyramid, 'toksvig', { precision: 'u8' }).levels[3].data).toEqual(chains.naive.levels[3].data);
  });
});

describe('V-groove of ±θ', () => {
  // Period of 2 texels: every level-1 texel holds one +θ and one −θ facet.
  const rows = [
    [5, 0.9962, 0.0038, 0.0077],
    [15, 0.9659, 0.0353, 0.0718],
    [30, 0.866, 0.1547, 0.3333],
    [45, 0.7071, 0.4142, 1.0],
  ];
  it.each(rows)('θ = %i°: |N_a| = cos θ, renormalized flat, σ² Toksvig, tan²θ across for LEAN', (theta, len, toks, tan2) => {
    const { chains } = chainsOf('grooves', { frequency: 32, angleDeg: theta }, 64);
    for (let level = 1; level < 7; level++) {
      const n = chains.naive.levels[level].data;
      const r = chains.renormalized.levels[level].data;
      const lean = chains.lean.levels[level].data;
      const count = n.length / 3;
      for (const t of [0, Math.min(7, count - 1), count - 1]) {
        expect(lengthAt(n, 3 * t)).toBeCloseTo(Math.cos(deg(theta)), 6);
        expect(n[3 * t]).toBeCloseTo(0, 6);
        expect([r[3 * t], r[3 * t + 1], r[3 * t + 2]]).toEqual([0, 0, 1]);
        expect(lean[5 * t + 2] - lean[5 * t] ** 2).toBeCloseTo(Math.tan(deg(theta)) ** 2, 5); // across
        expect(lean[5 * t + 3] - lean[5 * t + 1] ** 2).toBe(0); // along
      }
    }
    const L = lengthAt(chains.naive.levels[1].data, 0);
    expect(L).toBeCloseTo(len, 4);
    expect((1 - L) / L).toBeCloseTo(toks, 4);
    expect(Math.tan(deg(theta)) ** 2).toBeCloseTo(tan2, 4);
    expect(chains.vmf.levels[1].data[3]).toBeCloseTo(len, 4); // r̄ kept beside the unit direction
  });

  it('each technique turns θ = 30° at α = 0.5 into its own α′ (one blob where the truth is two spikes)', () => {
    const { chains } = chainsOf('grooves', { frequency: 32, angleDeg: 30 }, 64);
    const at = (t) => texelLobe(chains[t], 1, 0, { alpha: 0.5 });
    expect(at('naive').alpha).toBe(0.5);
    expect(at('renormalized').alpha).toBe(0.5);
    expect(at('toksvig').alpha).toBeCloseTo(0.625507, 5);
    expect(at('toksvig').alpha).toBeCloseTo(toksvigAlpha(Math.cos(deg(30)), 0.5), 6);
    expect(at('vmf').alpha).toBeCloseTo(0.711758, 5);
    expect(at('vmf').alpha).toBeCloseTo(vmfAlpha(Math.cos(deg(30)), 0.5), 6);
    expect(at('clean').alpha).toBeCloseTo(Math.sqrt(0.25 + 1 / 3), 5); // 0.76376
    const lean = at('lean');
    expect(lean.alpha).toBeCloseTo(at('clean').alpha, 6);
    expect(lean.alphaMajor).toBeCloseTo(Math.sqrt(2 * (1 / 3 + 0.125)), 5); // 0.95743, across
    expect(lean.alphaMinor).toBeCloseTo(0.5, 6); // along the groove: untouched
    for (const t of TECHNIQUES) expect(at(t).normal[2]).toBeCloseTo(1, 6); // every lobe points up
  });

  it('2 channels: z is rebuilt at unit length, so Toksvig sees no variance at all', () => {
    const { chains } = chainsOf('grooves', { frequency: 32, angleDeg: 30 }, 64, { channels: 2 });
    const lobe = texelLobe(chains.toksvig, 1, 0, { alpha: 0.5 });
    expect(lobe.length).toBe(1);
    expect(lobe.alpha).toBe(0.5);
    expect(texelLobe(chains.vmf, 1, 0, { alpha: 0.5 }).alpha).toBeCloseTo(0.711758, 5); // baked r̄ survives
  });

  it('the slope checker does the same in 2-D: flat and short at level 1, with an M_xy term', () => {
    const { chains } = chainsOf('checker', { frequency: 64, angleDeg: 20, azimuthDeg: 45 }, 64);
    const d = chains.naive.levels[1].data;
    expect(lengthAt(d, 0)).toBeCloseTo(Math.cos(deg(20)), 6);
    const lean = chains.lean.levels[1].data;
    expect(lean[4]).toBeCloseTo(Math.tan(deg(20)) ** 2 / 2, 6); // tan²θ cos φ sin φ
  });
});

describe('bumps at a distance', () => {
  const size = 256;
  const { pyramid, chains } = chainsOf('bumps', { frequency: 8 }, size); // 32 texels per cell
  const meanLength = (level) => {
    const d = chains.naive.levels[level].data;
    let s = 0;
    for (let o = 0; o < d.length; o += 3) s += lengthAt(d, o);
    return s / (d.length / 3);
  };

  it('mean |N_a| never grows with the level, and is < 1 at coarse levels', () => {
    const means = chains.naive.levels.map((_, l) => meanLength(l));
    expect(means[0]).toBeCloseTo(1, 6);
    for (let l = 1; l < means.length; l++) expect(means[l]).toBeLessThanOrEqual(means[l - 1] + 1e-6);
    expect(means[3]).toBeLessThan(0.97); // 8 texels: partial caps
    expect(means.map((m) => +m.toFixed(4))).toEqual([1, 0.9931, 0.9855, 0.9645, 0.9534, 0.9279, 0.9279, 0.9279, 0.9279]);
  });

  it('whole-cell levels hold the cap mean of the 32×32 texel centres, within 3e-3 of the exact cell mean', () => {
    const top = chains.naive.levels[8].data;
    expect(top[2]).toBeCloseTo(0.927911, 5);
    expect(top[2] - bumpCellMean({ frequency: 8 }).nz).toBeCloseTo(-0.00269, 4); // level-0 point sampling
    const clean = chains.clean.levels[8].data;
    expect(clean[2]).toBeCloseTo(pyramid[8].data[5] + pyramid[8].data[6], 6);
  });

  it('renormalized mips are unit length: the variance is gone', () => {
    for (const { data } of chains.renormalized.levels) {
      for (let o = 0; o < data.length; o += 3 * 97) expect(lengthAt(data, o)).toBeCloseTo(1, 6);
    }
  });

  it('the effective-roughness heatmap: Toksvig, vMF, CLEAN and LEAN widen the lobe at coarse levels', () => {
    const coarse = 6;
    for (const t of ['toksvig', 'vmf', 'clean', 'lean']) {
      const { alpha } = effectiveRoughness(chains[t], coarse, { alpha: 0.2 });
      expect(Math.min(...alpha)).toBeGreaterThan(0.3);
    }
    const renorm = effectiveRoughness(chains.renormalized, coarse, { exponent: 48 });
    expect(renorm.alpha[0]).toBeCloseTo(0.2, 6); // s = 48 ↔ α = 0.2
    expect(renorm.exponent[0]).toBeCloseTo(48, 3);
    expect(Number.isNaN(effectiveRoughness(chains.lean, coarse, { alpha: 0.2 }).length[0])).toBe(true);
  });
});

describe('LEAN/CLEAN moments are linear under averaging', () => {
  const size = 128;
  const map = createNormalMap('noise', { frequency: 8, octaves: 3, amplitude: 0.15 });
  const level0 = sampleLevel0(map, size);
  const pyramid = buildMomentPyramid(level0, size);
  const lean = buildChain(pyramid, 'lean');
  const clean = buildChain(pyramid, 'clean');
  const naive = buildChain(pyramid, 'naive');

  // The moments of the level-0 texels under a level-L texel, summed directly in float64.
  function direct(level, i, j) {
    const k = 2 ** level;
    const m = [0, 0, 0, 0, 0];
    for (let y = j * k; y < (j + 1) * k; y++) {
      for (let x = i * k; x < (i + 1) * k; x++) {
        const o = 3 * (y * size + x);
        const bx = level0[o] / level0[o + 2];
        const by = level0[o + 1] / level0[o + 2];
        [bx, by, bx * bx, by * by, bx * by].forEach((v, c) => { m[c] += v / (k * k); });
      }
    }
    return m;
  }

  it('mipping the moments equals the moments of the footprint, at every level', () => {
    for (let level = 1; level < levelCount(size); level++) {
      const ls = size >> level;
      for (const [i, j] of [[0, 0], [ls - 1, 0], [ls >> 1, ls - 1]]) {
        const want = direct(level, i, j);
        const got = lean.levels[level].data.subarray(5 * (j * ls + i), 5 * (j * ls + i) + 5);
        for (let c = 0; c < 5; c++) expect(got[c]).toBeCloseTo(want[c], 6);
        expect(clean.levels[level].data[3 * (j * ls + i) + 2]).toBeCloseTo(want[2] + want[3], 6);
      }
    }
  });

  it('level L + 1 is the 2×2 mean of level L (what trilinear hardware filtering relies on)', () => {
    const a = lean.levels[2].data;
    const b = lean.levels[3].data;
    const ls = size >> 2;
    for (let c = 0; c < 5; c++) {
      const mean = (a[c] + a[5 + c] + a[5 * ls + c] + a[5 * ls + 5 + c]) / 4;
      expect(b[c]).toBeCloseTo(mean, 7);
    }
  });

  it('whereas the slope of the mipped normal is not the mipped slope (the normal is nonlinear)', () => {
    let worst = 0;
    const n = naive.levels[3].data;
    const l = lean.levels[3].data;
    for (let t = 0; t < n.length / 3; t++) worst = Math.max(worst, Math.abs(n[3 * t] / n[3 * t + 2] - l[5 * t]));
    expect(worst).toBeGreaterThan(1e-3);
  });
});

describe('a 1024² map', () => {
  it('builds all six chains (moment pyramid included)', () => {
    const map = createNormalMap('mixed');
    const t0 = performance.now();
    const level0 = sampleLevel0(map, 1024);
    const t1 = performance.now();
    const { chains } = buildAllChains(level0, 1024, { precision: 'f16' });
    const t2 = performance.now();
    console.log(`1024² mixed: level 0 in ${(t1 - t0).toFixed(0)} ms; pyramid + 6 chains (f16, 3 ch) in ${(t2 - t1).toFixed(0)} ms`);
    for (const technique of TECHNIQUES) {
      expect(chains[technique].levels).toHaveLength(11);
      expect(chains[technique].levels[10].size).toBe(1);
    }
  });
});
