import { f16round } from '@petamoriken/float16';
import { describe, expect, it } from 'vitest';
import { buildAllChains } from '../../src/normals/buildChain.js';
import { createNormalMap } from '../../src/normals/createNormalMap.js';
import { halfBits, halfValue, roundHalfArray } from '../../src/normals/float16Bits.js';
import { texelLobe } from '../../src/normals/effectiveRoughness.js';
import { sampleLevel0 } from '../../src/normals/sampleLevel0.js';
import { storageCost, storageTable } from '../../src/normals/storageCost.js';
import { quantize, quantizeInPlace } from '../../src/normals/storagePrecision.js';
import { uploadLevels } from '../../src/normals/uploadLevels.js';

// Deterministic uniform [0, 1) (mulberry32).
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// Length errors |1 − |q(n)|| of `count` unit normals uniform on the cap z ∈ [0.5, 1]: a Monte Carlo
// estimate of the length noise 8-bit storage adds (Hill, "Specular Showdown", 2011, warns of it).
function lengthErrors(precision, count) {
  const rand = rng(2024);
  const errors = new Float64Array(count);
  let shorter = 0;
  for (let k = 0; k < count; k++) {
    const z = 0.5 + 0.5 * rand();
    const phi = 2 * Math.PI * rand();
    const s = Math.sqrt(1 - z * z);
    const L = Math.hypot(quantize(s * Math.cos(phi), precision), quantize(s * Math.sin(phi), precision), quantize(z, precision));
    errors[k] = Math.abs(1 - L);
    if (L < 1) shorter++;
  }
  errors.sort();
  const mean = errors.reduce((a, b) => a + b, 0) / count;
  return { mean, p99: errors[Math.floor(0.99 * count)], max: errors[count - 1], shorter: shorter / count };
}

describe('storage precision and the stored length', () => {
  it('8-bit: mean |1 − |n|| = 1.86e-3, p99 5.0e-3, max < √3/255, about half shorter', () => {
    const e = lengthErrors('u8', 200000);
    expect(e.mean).toBeGreaterThan(1.8e-3);
    expect(e.mean).toBeLessThan(1.92e-3);
    expect(e.p99).toBeGreaterThan(4.8e-3);
    expect(e.p99).toBeLessThan(5.3e-3);
    expect(e.max).toBeLessThan(Math.sqrt(3) / 255); // each component is off by at most 1/255
    expect(e.shorter).toBeGreaterThan(0.47);
    expect(e.shorter).toBeLessThan(0.51);
  });

  it('16-bit float: mean 1.1e-4, max < √3 · 2^−12; 32-bit: below 2e-7', () => {
    const h = lengthErrors('f16', 50000);
    expect(h.mean).toBeGreaterThan(0.9e-4);
    expect(h.mean).toBeLessThan(1.3e-4);
    expect(h.max).toBeLessThan(Math.sqrt(3) * 2 ** -12);
    expect(lengthErrors('f32', 20000).max).toBeLessThan(2e-7);
  });

  it('8-bit level 0 of a real map: runtime Toksvig sees false variance at mip 0', () => {
    const size = 128;
    const { chains } = buildAllChains(sampleLevel0(createNormalMap('noise'), size), size, { precision: 'u8' });
    let sum = 0;
    let rough = 0;
    for (let t = 0; t < size * size; t++) {
      const lobe = texelLobe(chains.toksvig, 0, t, { alpha: 0.1 });
      sum += Math.abs(1 - lobe.length);
      if (lobe.alpha > 0.11) rough++;
    }
    expect(sum / (size * size)).toBeGreaterThan(1.5e-3);
    expect(sum / (size * size)).toBeLessThan(2.5e-3);
    expect(rough / (size * size)).toBeGreaterThan(0.2); // α 0.1 → > 0.11 on a fifth or more of the texels
    expect(texelLobe(chains.vmf, 0, 0, { alpha: 0.1 }).alpha).toBeCloseTo(Math.sqrt(0.01 + 2 / 10000), 7); // baked r̄ = 1: κ = 10000
  });

  it('8-bit flat is (1/255, 1/255, 1): 0 has no code', () => {
    expect([quantize(0, 'u8'), quantize(1, 'u8'), quantize(-1, 'u8')]).toEqual([Math.fround(1 / 255), 1, -1]);
  });

  it('2 channels: the rebuilt normal is unit length at every precision', () => {
    const size = 64;
    const level0 = sampleLevel0(createNormalMap('mixed'), size);
    for (const precision of ['u8', 'f16', 'f32']) {
      const { chains } = buildAllChains(level0, size, { precision, channels: 2 });
      for (const technique of ['naive', 'renormalized', 'toksvig', 'vmf']) {
        let worst = 0;
        for (let level = 0; level < 7; level++) {
          const n = (size >> level) ** 2;
          for (let t = 0; t < n; t++) worst = Math.max(worst, Math.abs(1 - texelLobe(chains[technique], level, t, { alpha: 0.3 }).length));
        }
        expect(worst).toBeLessThan(1.2e-7); // float32 rounding of the rebuilt z only
      }
    }
  });
});

describe('binary16 rounding', () => {
  it('roundHalfArray and halfBits agree with f16round (random, ties, subnormals, overflow)', () => {
    const rand = rng(7);
    const xs = [0, -0, 65504, 65519.99, 65520, -65520, 2 ** -24, 2 ** -25, 3 * 2 ** -26, 2 ** -14, 1e-9, Infinity, NaN];
    for (let h = 0; h < 0x7c00; h += 37) xs.push(halfValue(h) + halfValue(h + 1) / 2 - halfValue(h) / 2); // midpoints
    for (let k = 0; k < 20000; k++) xs.push((rand() - 0.5) * 2 ** (Math.floor(rand() * 44) - 28));
    const data = Float32Array.from(xs);
    const want = Array.from(data, (x) => f16round(x));
    const got = roundHalfArray(data.slice());
    const bad = [];
    for (let i = 0; i < data.length; i++) {
      if (!Object.is(got[i], Math.fround(want[i]))) bad.push(['array', data[i], got[i], want[i]]);
      const viaBits = halfValue(halfBits(data[i]));
      if (!Object.is(viaBits, want[i]) && !(Number.isNaN(viaBits) && Number.isNaN(want[i]))) bad.push(['bits', data[i], viaBits, want[i]]);
    }
    expect(bad).toEqual([]);
    expect(data.length).toBeGreaterThan(20800);
  });

  it('quantizeInPlace equals quantize element by element', () => {
    const layout = [{ min: -1, max: 1 }, { min: 0, max: 0.37 }];
    const rand = rng(3);
    const data = Float32Array.from({ length: 2000 }, (_, i) => (i % 2 ? 0.4 * rand() : 2.2 * rand() - 1.1));
    for (const precision of ['u8', 'f16', 'f32']) {
      const q = quantizeInPlace(data.slice(), layout, precision);
      const bad = q.filter((v, i) => v !== Math.fround(quantize(data[i], precision, layout[i % 2].min, layout[i % 2].max)));
      expect(bad.length).toBe(0);
    }
  });
});

describe('storage cost', () => {
  const texels = 1398101; // a 1024² chain

  it('bytes per technique × precision × channels for 1024²', () => {
    const cost = (technique, precision, channels) => storageCost({ technique, precision, channels, size: 1024 });
    expect(cost('naive', 'u8', 3).bytes).toBe(texels * 3);
    expect(cost('naive', 'u8', 3).uploadBytes).toBe(texels * 4); // RGBA8
    expect(cost('naive', 'u8', 2).uploadBytes).toBe(texels * 2); // RG8
    expect(cost('toksvig', 'f16', 3).bytes).toBe(texels * 6);
    expect(cost('vmf', 'f16', 2)).toMatchObject({ components: 3, uploadComponents: 4, varianceKept: true });
    expect(cost('lean', 'f16', 2)).toMatchObject({ bytes: texels * 10, uploadBytes: texels * 10, channels: null, formats: ['RGBA', 'R'] });
    expect(cost('clean', 'f32', 3)).toMatchObject({ bytes: texels * 12, uploadBytes: texels * 16 });
    expect(cost('toksvig', 'u8', 2).varianceKept).toBe(false);
    expect(cost('renormalized', 'f32', 3)).toMatchObject({ levels: 11, texels, varianceKept: false });
  });

  it('the table lists 30 combinations', () => {
    const rows = storageTable(256);
    expect(rows).toHaveLength(30);
    expect(rows.filter((r) => r.technique === 'lean')).toHaveLength(3);
  });
});

describe('uploadLevels', () => {
  it('byte, half and float arrays decode back to the chain values; 3 channels are padded to RGBA', () => {
    const size = 64;
    const level0 = sampleLevel0(createNormalMap('bumps'), size);
    for (const precision of ['u8', 'f16', 'f32']) {
      const { chains } = buildAllChains(level0, size, { precision });
      for (const technique of ['naive', 'lean']) {
        const chain = chains[technique];
        const textures = uploadLevels(chain);
        expect(textures.map((t) => t.format)).toEqual(technique === 'lean' ? ['RGBA', 'R'] : ['RGBA']);
        const tex = textures[0];
        expect(tex.mipmaps.map((m) => m.width)).toEqual([64, 32, 16, 8, 4, 2, 1]);
        const { data } = tex.mipmaps[2];
        const stored = chain.levels[2].data;
        for (let t = 0; t < 16 * 16; t += 7) {
          for (let k = 0; k < 4; k++) {
            const raw = data[4 * t + k];
            const { min, max } = tex.ranges[k];
            const value = precision === 'u8' ? Math.fround(min + ((max - min) * raw) / 255) : precision === 'f16' ? halfValue(raw) : raw;
            const want = tex.names[k] === 'pad' ? 1 : stored[t * chain.components + k]; // naive pads alpha with 1
            expect(value).toBe(Math.fround(want));
          }
        }
      }
    }
  });
});
