import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  benchCsv, benchResults, benchTable, DEFAULT_DOMAIN, gpuPrecisionFor, measuredCosts,
} from '../../src/methods/benchResults.js';
import { methodError } from '../../src/methods/advisor.js';
import { METHODS, methodsOfKind } from '../../src/methods/methods.js';
import { sceneById, SCENES } from '../../src/methods/scenes.js';
import { cpuInputs, spreadOf, timeMethodsCpu } from '../../src/methods/timeMethodsCpu.js';
import { methodCall, timingDomain, timingFragment } from '../../src/gl/timeMethodsGpu.js';

const chunks = Object.fromEntries(readdirSync('shaders').filter((f) => f.endsWith('.glsl'))
  .map((f) => [f.replace(/\.glsl$/, ''), readFileSync(`shaders/${f}`, 'utf8')]));

/** A clock that advances by `step` ms per reading: timings become exact and predictable. */
function fakeClock(step) {
  let t = 0;
  return () => (t += step);
}

describe('timing statistics', () => {
  it('spreadOf gives median, min and max of the finite samples', () => {
    expect(spreadOf([3, 1, 2])).toEqual({ median: 2, min: 1, max: 3 });
    expect(spreadOf([4, 1, 3, 2])).toEqual({ median: 2.5, min: 1, max: 4 });
    expect(spreadOf([5, NaN, Infinity, 1])).toEqual({ median: 3, min: 1, max: 5 });
    expect(spreadOf([])).toEqual({ median: NaN, min: NaN, max: NaN });
  });
});

describe('timeMethodsCpu', () => {
  it('inputs cover the scene domains with varying cosines', () => {
    const d = cpuInputs('dielectric', 64);
    expect(d).toHaveLength(64);
    expect(new Set(d.map((a) => a[0])).size).toBe(64);
    for (const [c, nI, nT] of d) {
      expect(c).toBeGreaterThan(0);
      expect(c).toBeLessThan(1);
      expect(nI).toBe(1);
      expect(nT).toBeGreaterThanOrEqual(1.3);
      expect(nT).toBeLessThanOrEqual(1.7);
    }
    expect(cpuInputs('conductor', 12).map((a) => a.length)).toEqual(Array(12).fill(4));
  });

  it('turns a clock into ns per evaluation with the spread over repeats', async () => {
    // Every reading advances 2 ms: each timed block reads the clock twice, so it "takes" 2 ms,
    // which meets minMs = 2 on the first try (1 loop of 16 inputs): 2e6 ns / 16 = 125000 ns.
    const progress = [];
    const r = await timeMethodsCpu({
      methods: METHODS.slice(0, 3), repeats: 3, minMs: 2, count: 16, now: fakeClock(2),
      onProgress: (done, total) => progress.push([done, total]),
    });
    expect(Object.keys(r.methods)).toEqual(METHODS.slice(0, 3).map((m) => m.id));
    for (const m of Object.values(r.methods)) {
      expect(m.nsPerEval).toEqual({ median: 125000, min: 125000, max: 125000 });
      expect(m.samples).toHaveLength(3);
      expect(m.evaluations).toBe(16);
    }
    expect(progress.at(-1)).toEqual([12, 12]); // 3 calibrations + 3 × 3 timed blocks
    expect(Number.isFinite(r.sink)).toBe(true);
  });

  it('calibrates the loop count up to minMs and measures real time with the real clock', async () => {
    const r = await timeMethodsCpu({ methods: [METHODS[4]], repeats: 2, minMs: 3, count: 256 });
    const m = r.methods['schlick-mul'];
    expect(m.evaluations).toBeGreaterThan(256); // more than one loop was needed for 3 ms
    expect(m.nsPerEval.median).toBeGreaterThan(0);
    expect(m.nsPerEval.median).toBeLessThan(1e5);
  });

  it('an aborted signal rejects with its reason', async () => {
    const controller = new AbortController();
    controller.abort(new Error('stop'));
    await expect(timeMethodsCpu({ signal: controller.signal })).rejects.toThrow('stop');
    const late = new AbortController();
    const run = timeMethodsCpu({ minMs: 1, count: 16, onProgress: (done) => { if (done === 2) late.abort(new Error('later')); }, signal: late.signal });
    await expect(run).rejects.toThrow('later');
  });
});

describe('the GPU timing shader', () => {
  it('calls every method\'s own function of fresnelMethods.glsl with its declared arity', () => {
    const source = chunks.fresnelMethods;
    for (const m of METHODS) {
      const call = methodCall(m);
      const name = call.slice(0, call.indexOf('('));
      const declared = new RegExp(`float ${name}\\(([^)]*)\\)`).exec(source);
      expect(declared, name).not.toBeNull();
      expect(call.split(',').length).toBe(declared[1].split(',').length);
    }
  });

  it('loops a uniform count, feeds each result into the next input and accumulates the output', () => {
    const f = timingFragment(methodCall(METHODS[0]), 'mediump', chunks);
    expect(f).toMatch(/^#version 300 es\nprecision mediump float;/);
    expect(f).toContain('float fm_exact_cg(');
    expect(f).toMatch(/uniform int uLoops;[\s\S]*for \(int i = 0; i < uLoops; i\+\+\)/);
    expect(f).toContain('float f = fm_exact_cg(c, v.x, v.y);');
    expect(f).toContain('sum += f;');
    expect(f).toMatch(/c = fract\(c \* [0-9.]+ \+ f \+ 0\.1\);/); // the next input depends on f
    expect(f).toMatch(/outColor = vec4\(fract\(sum\)/);
    expect(f).toContain('gl_FragCoord.xy / uSize'); // per-pixel inputs
    const base = timingFragment(null, 'highp', chunks);
    expect(base).not.toContain('fm_'); // the baseline: same loop, F(c) = c
    expect(base).toContain('float f = c;');
    expect(() => timingFragment('x', 'lowp', chunks)).toThrow(RangeError);
  });

  it('spans the plastic indices and the gold-to-aluminium metals', () => {
    expect(timingDomain('dielectric')).toEqual({ lo: [1, 1.3, 0, 0], hi: [1, 1.7, 0, 0] });
    const { lo, hi } = timingDomain('conductor');
    expect(lo[0]).toBeLessThan(hi[0]); // gold's n at 550 nm is below aluminium's
    expect(lo.every(Number.isFinite) && hi.every(Number.isFinite)).toBe(true);
  });
});

describe('benchResults', () => {
  const gpu = {
    timer: 'test timer', device: { renderer: 'Test GPU', vendor: 'Test', version: 'WebGL 2.0' },
    size: 8, loops: 4, passes: 1, repeats: 2, evaluationsPerPass: 256,
    results: Object.fromEntries(['highp', 'mediump'].map((p, j) => [p, Object.fromEntries(METHODS.map((m, i) => [
      m.id, { nsPerEval: { median: i + 1 + j * 10, min: i + j * 10, max: i + 2 + j * 10 }, samples: [i, i + 2] },
    ]))])),
  };
  const cpu = { methods: Object.fromEntries(METHODS.map((m) => [m.id, { nsPerEval: { median: 50, min: 40, max: 60 }, samples: [40, 60] }])) };
  const side = (ms) => ({ msPerFrame: { median: ms, min: ms, max: ms }, pixels: 7500 });
  const frames = {
    width: 150, height: 50, ratio: 2, plainRatio: 0.8,
    spheres: side(1), spheresView: side(3), spheresOnePass: side(4), copy: side(0.5), threePhysical: side(2), threePlain: side(1.25),
  };
  const results = benchResults({ gpu, cpu, frames, meta: { date: 'today', config: { size: 'tiny' } } });

  it('has the shape bench/results.json promises', () => {
    expect(results.device).toMatchObject({ renderer: 'Test GPU', timer: 'test timer' });
    expect(results.methods.map((m) => m.id)).toEqual(METHODS.map((m) => m.id));
    for (const m of results.methods) {
      expect(m.gpu.nsPerEval).toEqual(gpu.results.highp[m.id].nsPerEval);
      expect(m.gpu.mediump.nsPerEval).toEqual(gpu.results.mediump[m.id].nsPerEval);
      expect(m.cpu.nsPerEval).toEqual({ median: 50, min: 40, max: 60 });
      expect(m.error.scene).toBe(DEFAULT_DOMAIN[m.kind]);
      for (const p of ['fp64', 'fp32', 'fp16']) {
        expect(Number.isFinite(m.error[p].max)).toBe(true);
        expect(Number.isFinite(m.error[p].mean)).toBe(true);
        expect(m.error[p].mean).toBeLessThanOrEqual(m.error[p].max);
      }
    }
    expect(results.frames).toMatchObject({ spheres: { msPerFrame: { median: 1 } }, threePhysical: { msPerFrame: { median: 2 } }, ratio: 2 });
    expect(results.frames).toMatchObject({ spheresView: { msPerFrame: { median: 3 } }, copy: { msPerFrame: { median: 0.5 } }, plainRatio: 0.8 });
    expect(benchTable(results)).toMatch(/hero, one full-screen pass\s+4\.000 \[4\.000, 4\.000\]/);
    expect(JSON.parse(JSON.stringify(results))).toEqual(results); // plain JSON, nothing lost
  });

  it('errors are the advisor\'s: exact forms at rounding level, Schlick at the formula\'s error', () => {
    const byId = Object.fromEntries(results.methods.map((m) => [m.id, m.error]));
    expect(byId['exact-cg'].fp64.max).toBeLessThan(1e-12);
    expect(byId['exact-cg'].fp32.max).toBeGreaterThan(1e-9);
    expect(byId['exact-cg'].fp16.max).toBeGreaterThan(byId['exact-cg'].fp32.max);
    expect(byId['schlick-mul'].fp64.max).toBeCloseTo(0.0683, 4);
    expect(byId['conductor-schlick'].fp64.max).toBeCloseTo(0.130, 3);
  });

  it('feeds measured GPU costs at the scene\'s precision to the advisor', () => {
    expect(gpuPrecisionFor('fp16')).toBe('mediump');
    expect(gpuPrecisionFor('fp32')).toBe('highp');
    const plastic = measuredCosts(results, sceneById('plastic'));
    expect(Object.keys(plastic)).toEqual(methodsOfKind('dielectric').map((m) => m.id));
    expect(plastic['exact-cg']).toBe(1);
    expect(measuredCosts(results, sceneById('phone-mediump'))['exact-cg']).toBe(11);
    expect(measuredCosts(results, sceneById('plastic'), 'cpu')['exact-cg']).toBe(50);
    expect(measuredCosts(null, sceneById('plastic'))).toEqual({});
    expect(measuredCosts(benchResults({ cpu }), sceneById('plastic'))).toEqual({}); // no GPU run
    // Costs here rise in table order, so exact c/g is the cheapest of all and passes every budget.
    expect(results.recommendations.plastic.invisible.methodId).toBe('exact-cg');
    expect(results.recommendations.plastic.acceptable.methodId).toBe('exact-cg');
    expect(results.recommendations['glass-inside'].acceptable.methodId).toBe('exact-cg');
    expect(results.recommendations.plastic.costSource).toMatch(/measured GPU/);
    expect(Object.keys(results.recommendations)).toEqual(SCENES.map((s) => s.id));
  });

  it('carries the errors read back on the GPU as error.gpuHighp and error.gpuMediump, beside fp64/fp32/fp16', () => {
    // Read-back errors shaped as gpuErrors.errorsFromValues gives them; here the JS twin's own
    // float32 and float16 errors stand in for a GPU that computes exactly like the emulation.
    const gpuErrors = Object.fromEntries(Object.values(DEFAULT_DOMAIN).map((sceneId) => {
      const scene = sceneById(sceneId);
      const of = (p) => Object.fromEntries(methodsOfKind(scene.kind).map((m) => [m.id, methodError(scene, m, p)]));
      return [sceneId, { highp: of('fp32'), mediump: of('fp16') }];
    }));
    const withGpu = benchResults({ gpu, cpu, gpuErrors, meta: { gpuReadbackError: null } });
    for (const m of withGpu.methods) {
      expect(m.error.gpuHighp).toEqual(m.error.fp32);
      expect(m.error.gpuMediump).toEqual(m.error.fp16);
      expect(Object.keys(m.error.gpuHighp)).toEqual(['max', 'mean', 'rms', 'maxCodes', 'thetaAtMaxDeg', 'nanCount']);
    }
    expect(withGpu.device.gpuReadbackError).toBeNull();
    expect(results.methods.every((m) => m.error.gpuHighp === null && m.error.gpuMediump === null)).toBe(true);
    const { columns } = benchCsv(withGpu);
    expect(columns.error_gpu_highp_max).toEqual(withGpu.methods.map((m) => m.error.gpuHighp.max));
    expect(columns.error_gpu_mediump_mean).toEqual(withGpu.methods.map((m) => m.error.gpuMediump.mean));
    expect(benchCsv(results).columns.error_gpu_highp_max.every(Number.isNaN)).toBe(true);
    expect(benchTable(withGpu)).toMatch(/GPU highp\s+GPU mediump/);
    expect(benchTable(withGpu)).toContain('read back from this GPU');
    expect(benchTable(results)).not.toContain('read back from this GPU');
    // The GPU costs can be read in a precision other than the scene's (the read-back's).
    expect(measuredCosts(results, sceneById('plastic'), 'gpu', 'mediump')['exact-cg']).toBe(11);
  });

  it('without a run: errors and static costs only', () => {
    const bare = benchResults();
    expect(bare.methods.every((m) => m.gpu === null && m.cpu === null)).toBe(true);
    expect(bare.frames).toBeNull();
    expect(bare.recommendations['glass-inside'].costSource).toBe('static count');
  });

  it('CSV columns and the text table carry every method', () => {
    const { columns } = benchCsv(results);
    expect(columns.method).toEqual(METHODS.map((m) => m.id));
    for (const values of Object.values(columns)) expect(values).toHaveLength(METHODS.length);
    expect(columns.gpu_highp_ns_median[0]).toBe(1);
    expect(columns.gpu_mediump_ns_max[0]).toBe(12);
    const table = benchTable(results);
    for (const m of METHODS) expect(table).toContain(m.id);
    expect(table).toContain('1.000 [0.000, 2.000]');
    expect(table).toMatch(/hero\/peer 2\.00/);
    expect(table).toContain('Test GPU');
  });
});
