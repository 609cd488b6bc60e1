import { describe, expect, it } from 'vitest';
import { buildChainsFor, mergeBuilds, splitTechniques, transferablesOf } from '../../src/normals/buildChainsFor.js';
import { createChainBuilder, workerCount } from '../../src/normals/createChainBuilder.js';
import { TECHNIQUES } from '../../src/normals/techniqueLayout.js';
import { chainProblemText } from '../../src/panels/normal-mips/words.js';

const request = { kind: 'bumps', params: { frequency: 4, edgeAngleDeg: 30 }, size: 32, precision: 'f16', channels: 3 };

describe('buildChainsFor', () => {
  it('builds every technique and times itself with the given clock', () => {
    let t = 0;
    const { chains, pyramid, ms } = buildChainsFor(request, () => (t += 5));
    expect(Object.keys(chains)).toEqual([...TECHNIQUES]);
    expect(pyramid.map((l) => l.size)).toEqual([32, 16, 8, 4, 2, 1]);
    expect(chains.lean.levels).toHaveLength(6);
    expect(ms).toBe(5);
  });

  it('lists each buffer once (Toksvig shares naive\'s levels), so postMessage can transfer them', () => {
    const result = buildChainsFor(request);
    const buffers = transferablesOf(result);
    expect(new Set(buffers).size).toBe(buffers.length);
    expect(buffers).toContain(result.chains.toksvig.levels[0].data.buffer);
    expect(buffers).toContain(result.pyramid[0].data.buffer);
    // naive and toksvig share; the other four chains and the pyramid own one buffer per level,
    // and so does each packed texture (lean has two; toksvig's packing is naive's)
    const textures = Object.entries(result.uploads).filter(([t]) => t !== 'toksvig').reduce((n, [, list]) => n + list.length, 0);
    expect(result.uploads.toksvig).toBe(result.uploads.naive);
    expect(buffers).toHaveLength(6 * (5 + 1 + textures));
  });
});

describe('split builds', () => {
  it('splits the techniques into disjoint shares that cover them all, Toksvig with naive', () => {
    for (const parts of [1, 2, 3, 8]) {
      const shares = splitTechniques(parts);
      expect(shares.length).toBe(Math.min(parts, 3));
      expect(shares.flat().sort()).toEqual([...TECHNIQUES].sort());
      expect(shares.find((s) => s.includes('toksvig'))).toContain('naive');
    }
    expect(workerCount(1)).toBe(1);
    expect(workerCount(2)).toBe(2);
    expect(workerCount(16)).toBe(3);
  });

  it('merges shares into what one build gives, value for value', () => {
    const whole = buildChainsFor(request);
    const merged = mergeBuilds(splitTechniques(3).map((techniques) => buildChainsFor({ ...request, techniques })));
    expect(Object.keys(merged.chains)).toEqual([...TECHNIQUES]);
    for (const t of TECHNIQUES) {
      expect(merged.chains[t].levels.map((l) => [...l.data])).toEqual(whole.chains[t].levels.map((l) => [...l.data]));
      expect(merged.uploads[t].map((u) => u.mipmaps.map((m) => [...m.data]))).toEqual(whole.uploads[t].map((u) => u.mipmaps.map((m) => [...m.data])));
    }
    expect(() => buildChainsFor({ ...request, techniques: ['toksvig'] })).toThrow(/with naive/);
  });
});

describe('createChainBuilder without a Worker (Node): the same build on this thread', () => {
  it('resolves the newest request and drops superseded ones unbuilt', async () => {
    const builder = createChainBuilder();
    expect(builder.where).toBe('main thread');
    expect(builder.workers).toBe(0);
    const first = builder.build(request);
    const second = builder.build({ ...request, size: 16 });
    expect(await first).toBeNull();
    const result = await second;
    expect(result.where).toBe('main thread');
    expect(result.workers).toBe(0);
    expect(result.chains.naive.size).toBe(16);
    builder.dispose();
  });

  it('says why it builds on this thread when workers were asked for, and is silent when they were not', () => {
    expect(createChainBuilder().problem).toEqual({ reason: 'noWorkers' });
    expect(chainProblemText(createChainBuilder().problem)).toMatch(/no Web Workers: the chains are built on the page’s thread/);
    expect(createChainBuilder({ useWorker: false }).problem).toBeNull();
    expect(chainProblemText(null)).toBe('');
  });

  it('falls back and says so when a worker cannot be constructed', async () => {
    const saved = globalThis.Worker;
    globalThis.Worker = class { constructor() { throw new Error('blocked by the page’s policy'); } };
    try {
      const builder = createChainBuilder({ workers: 2 });
      expect(builder.where).toBe('main thread');
      expect(chainProblemText(builder.problem)).toMatch(/could not start \(blocked by the page’s policy\)/);
      expect((await builder.build({ ...request, size: 16 })).chains.naive.size).toBe(16);
    } finally {
      if (saved === undefined) delete globalThis.Worker; else globalThis.Worker = saved;
    }
  });

  it('rejects a bad request with the map\'s own message', async () => {
    const builder = createChainBuilder({ useWorker: false });
    await expect(builder.build({ ...request, size: 30 })).rejects.toThrow(/power of two/);
  });
});
