// Properties of what a panel reads from storage and from the page that embeds it: the benchmark's
// results kept for the session, the theme kept in localStorage, every message type of the API
// (parseMessage), and the embed page's own options in its link. Whatever arrives, nothing throws,
// what is kept has the shape the page uses, and what is refused is named.
import { afterEach, describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { readCachedResults } from '../../src/panels/speed-accuracy/cachedResults.js';
import { benchResults, DEFAULT_DOMAIN, measuredCosts } from '../../src/methods/benchResults.js';
import { METHODS } from '../../src/methods/methods.js';
import { SCENES, sceneById } from '../../src/methods/scenes.js';
import { loadTheme } from '../../src/ui/theme.js';
import { parseMessage } from '../../src/host/messageApi.js';
import { EMBED_KEYS, readEmbedOptions } from '../../src/host/readEmbedOptions.js';
import { anyJson, anyText, anyValue, ownObject, PROTOTYPE_NAMES } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

const positive = fc.double({ min: 1e-3, max: 1e6, noNaN: true });
// A time less a baseline's may be below 0 on a software GPU.
const time = fc.double({ min: -50, max: 1e6, noNaN: true });
const stats = fc.tuple(time, time, time).map((v) => v.sort((a, b) => a - b)).map(([min, median, max]) => ({ median, min, max }));
const frameStats = fc.tuple(positive, positive, positive).map((v) => v.sort((a, b) => a - b)).map(([min, median, max]) => ({ median, min, max }));
const timing = fc.record({ nsPerEval: stats, samples: fc.array(positive, { maxLength: 5 }) });
const someOf = (arb) => fc.array(fc.option(arb, { nil: undefined }), { minLength: METHODS.length, maxLength: METHODS.length });
const errorSummary = fc.record({
  max: positive, mean: positive, rms: positive, maxCodes: fc.integer({ min: 0, max: 1000 }),
  thetaAtMax: fc.option(fc.constantFrom(0, Math.PI / 4, Math.PI / 3, Math.PI / 2), { nil: null }), nanCount: fc.integer({ min: 0, max: 9 }),
});
const text = fc.option(fc.string({ maxLength: 30 }), { nil: null });

/** A run's measurements as runBenchmark gives them to benchResults, any of them missing. */
/** timeFrames' result from six spreads: the hero and the clear-coated peer, and (parts) the rest. */
function framesOf({ sides: [hero, peer, view, onePass, copy, plain], parts, w }, timer) {
  const side = (msPerFrame) => ({ msPerFrame, pixels: 9 });
  const frames = { width: w, height: w, ratio: hero.median / peer.median, spheres: { ...side(hero), timer }, threePhysical: side(peer) };
  if (!parts) return frames;
  return { ...frames, spheresView: side(view), spheresOnePass: side(onePass), copy: side(copy), threePlain: side(plain), plainRatio: hero.median / plain.median };
}

const run = fc.record({
  highp: someOf(timing), mediump: someOf(timing), cpu: someOf(timing), errors: someOf(fc.tuple(errorSummary, errorSummary)),
  renderer: text, timer: text, gpuError: text,
  // The frame timing (timeFrames.js): the hero and the clear-coated peer, and perhaps its other parts.
  frames: fc.option(fc.record({ sides: fc.array(frameStats, { minLength: 6, maxLength: 6 }), parts: fc.boolean(), w: fc.integer({ min: 1, max: 4096 }) }), { nil: null }),
}).map((m) => {
  const byId = (list) => Object.fromEntries(METHODS.flatMap((method, i) => (list[i] ? [[method.id, list[i]]] : [])));
  const gpuErrors = {};
  METHODS.forEach((method, i) => {
    if (!m.errors[i]) return;
    const scene = DEFAULT_DOMAIN[method.kind];
    ((gpuErrors[scene] ??= {}).highp ??= {})[method.id] = m.errors[i][0];
    (gpuErrors[scene].mediump ??= {})[method.id] = m.errors[i][1];
  });
  const hasGpu = m.highp.some(Boolean) || m.mediump.some(Boolean);
  return benchResults({
    gpu: hasGpu ? {
      results: { highp: byId(m.highp), mediump: byId(m.mediump) }, device: { renderer: m.renderer, vendor: null, version: 'WebGL 2.0' },
      timer: m.timer, size: 256, loops: 8, passes: 3, bestOf: 5, repeats: 2, evaluationsPerPass: 65536,
    } : null,
    cpu: m.cpu.some(Boolean) ? { methods: byId(m.cpu), where: 'worker' } : null,
    frames: m.frames ? framesOf(m.frames, m.timer) : null,
    gpuErrors: Object.keys(gpuErrors).length ? gpuErrors : null,
    meta: { date: '2026-12-04T05:00:00.000Z', userAgent: 'test', config: { size: 'tiny' }, gpuError: m.gpuError, gpuReadbackError: null, device: null },
  });
});

/** JSON as storage keeps it, θ rounded: degrees → radians → degrees may move the last bit. */
const stored = (results) => JSON.parse(JSON.stringify(results, (k, v) => (k === 'thetaAtMaxDeg' && v !== null ? Math.round(v * 1e9) / 1e9 : v)));

describe('the benchmark\'s results kept for the session', () => {
  it('a run written to storage reads back as the same results', () => {
    check(fc.property(run, (results) => {
      expect(stored(readCachedResults(JSON.stringify(results)))).toEqual(stored(results));
    }), 60);
  });

  it('whatever storage holds, it reads as null or as results the panel can use', () => {
    const edited = run.chain((results) => fc.tuple(fc.constantFrom(...'version methods device frames date config'.split(' ')), anyJson)
      .map(([key, value]) => ({ ...JSON.parse(JSON.stringify(results)), [key]: value })));
    const rowEdited = run.chain((results) => fc.tuple(fc.nat(METHODS.length - 1), fc.constantFrom('gpu', 'cpu', 'error', 'id', 'kind'), anyJson)
      .map(([i, key, value]) => { const r = JSON.parse(JSON.stringify(results)); r.methods[i][key] = value; return r; }));
    check(fc.property(fc.oneof(anyText, anyJson.map((v) => JSON.stringify(v)), fc.oneof(edited, rowEdited).map((v) => JSON.stringify(v)), fc.constant(null)), (raw) => {
      const results = readCachedResults(raw);
      if (results === null) return;
      expect(results.methods.map((m) => m.id)).toEqual(METHODS.map((m) => m.id));
      for (const scene of SCENES) for (const source of ['gpu', 'cpu']) {
        for (const ns of Object.values(measuredCosts(results, scene, source))) expect(Number.isFinite(ns)).toBe(true);
      }
      for (const row of results.methods) for (const e of Object.values(row.error).filter((x) => x && typeof x === 'object')) {
        expect(typeof e.max).toBe('number');
      }
      expect(sceneById(DEFAULT_DOMAIN.dielectric)).toBeTruthy();
    }), 200);
  });
});

describe('the theme kept in localStorage', () => {
  const original = globalThis.localStorage;
  afterEach(() => { globalThis.localStorage = original; });

  it('whatever is kept, or a storage that throws, gives dark or light and projector on or off', () => {
    check(fc.property(fc.oneof(anyText, anyJson.map((v) => JSON.stringify(v)), fc.constant(null)), fc.boolean(), (held, refuses) => {
      globalThis.localStorage = /** @type {any} */ ({ getItem: () => { if (refuses) throw new Error('SecurityError'); return held; } });
      const theme = loadTheme();
      expect(['dark', 'light']).toContain(theme.scheme);
      expect(typeof theme.projector).toBe('boolean');
    }), 200);
  });
});

describe('every message type of the API', () => {
  const TYPES = ['get', 'set', 'reset', 'snapshot', 'lock', 'unlock', 'hide', 'show', 'theme', 'projector', 'reducedMotion', 'audio', 'pause', 'resume',
    ...PROTOTYPE_NAMES, 'changed', 'state', 'ready', ''].map((t) => `fresnel-lab:${t}`);
  const FIELDS = ['params', 'to', 'width', 'height', 'id', 'keys', 'theme', 'on', ...PROTOTYPE_NAMES];
  const message = fc.oneof(
    anyValue,
    fc.tuple(fc.oneof(fc.constantFrom(...TYPES), anyValue), fc.array(fc.tuple(fc.constantFrom(...FIELDS), anyValue), { maxLength: 4 }))
      .map(([type, entries]) => ownObject([['type', type], ...entries])),
  );

  it('any data is a message of one accepted shape, or nothing; it never throws', () => {
    check(fc.property(message, (data) => {
      const m = parseMessage(data);
      if (m === null) return;
      switch (m.kind) {
        case 'set': expect(typeof m.params === 'object' && m.params !== null && !Array.isArray(m.params)).toBe(true); break;
        case 'reset': expect(['start', 'defaults']).toContain(m.to); break;
        case 'snapshot':
          for (const v of [m.width, m.height]) expect(v === null || (Number.isInteger(v) && v >= 1 && v <= 4096)).toBe(true);
          expect(m.id === null || (typeof m.id === 'string' && m.id.length <= 64)).toBe(true);
          break;
        case 'theme': expect(['light', 'dark']).toContain(m.theme); break;
        case 'projector': case 'reducedMotion': case 'audio': expect(typeof m.on).toBe('boolean'); break;
        case 'lock': case 'unlock': case 'hide': case 'show':
          expect(m.keys === null || (m.keys.length <= 64 && m.keys.every((k) => typeof k === 'string' && k.length <= 64))).toBe(true);
          break;
        default: expect(['get', 'pause', 'resume']).toContain(m.kind);
      }
    }), 400);
  });
});

describe('the embed page\'s options in its link', () => {
  it('any query gives options of the documented kinds; each refused value is named', () => {
    const pair = fc.tuple(fc.oneof(fc.constantFrom(...EMBED_KEYS), anyText), anyText);
    check(fc.property(fc.array(pair, { maxLength: 6 }), (pairs) => {
      const search = new URLSearchParams();
      for (const [k, v] of pairs) search.append(k, v);
      const { options, problems } = readEmbedOptions(search);
      expect([null, 'light', 'dark']).toContain(options.theme);
      for (const k of ['projector', 'reducedMotion']) expect([null, true, false]).toContain(options[k]);
      for (const k of ['audio', 'controls']) expect(typeof options[k]).toBe('boolean');
      for (const k of ['lock', 'hide']) expect(options[k].length <= 64 && options[k].every((x) => typeof x === 'string' && x.trim() === x && x)).toBe(true);
      expect(options.parentOrigin === null || options.parentOrigin === 'none' || /^https?:\/\/[^/?#]+$/.test(options.parentOrigin)).toBe(true);
      for (const p of problems) expect(EMBED_KEYS).toContain(p.key);
      expect(problems.length > 0 || options.parentOrigin !== 'none').toBe(true);
    }), 300);
  });
});
