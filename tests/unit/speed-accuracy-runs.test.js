import {
  beforeAll, describe, expect, it, vi,
} from 'vitest';
import { createSpeedAccuracyRuns } from '../../src/panels/speed-accuracy/runs.js';
import { formatCodes, formatNs, shortDecimal } from '../../src/panels/speed-accuracy/formatMeasures.js';
import { readBackProblem } from '../../src/panels/speed-accuracy/readBackProblem.js';
import {
  describeView, speedAccuracyView, statusText, viewCsv,
} from '../../src/panels/speed-accuracy/words.js';
import { schema } from '../../src/panels/speed-accuracy/schema.js';
import { benchResults } from '../../src/methods/benchResults.js';
import { METHODS } from '../../src/methods/methods.js';
import { sceneById } from '../../src/methods/scenes.js';
import { WebGL2Unavailable } from '../../src/gl/webgl2Unavailable.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { offsetErrors } from './standInReadBack.js';

const defaults = () => Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, spec.default]));
const flush = () => new Promise((resolve) => { setTimeout(resolve, 0); });
const MINUS = '\u2212';

/** A promise with its resolve and reject at hand. */
function deferred() {
  let resolve;
  let reject;
  const promise = new Promise((res, rej) => { resolve = res; reject = rej; });
  return { promise, resolve, reject };
}

/** Results of a benchmark run: every method timed on the GPU (highp) at 10 + its index ns, spread ±1. */
function timedResults() {
  const highp = Object.fromEntries(METHODS.map((m, i) => [m.id, {
    nsPerEval: { median: 10 + i, min: 9 + i, max: 11 + i }, samples: [],
  }]));
  return benchResults({ gpu: { results: { highp } }, meta: { date: '2026-01-01T00:00:00Z', device: { renderer: 'Stand-in GPU' } } });
}

/**
 * A measurement as the read-back gives it: every method of the scene's kind off the float64
 * reference by a constant of its own (1e-4 × (index + 1)), through the same statistics.
 */
function readBackOf(scene) {
  const errors = offsetErrors(scene);
  return { errors, probe: { mediumpIsFullPrecision: true, mediumpBits: 24 }, claimed: null, device: { renderer: 'Stand-in GPU' } };
}

function setup({ stored = null, values = defaults() } = {}) {
  const events = [];
  const measurements = []; // { scene, precision, ...deferred }
  const cache = new Map();
  const benchmarks = []; // { options, ...deferred }
  const saved = [];
  let clock = 1000;
  const runs = createSpeedAccuracyRuns({
    values,
    readBack: {
      cached: (scene, precision) => cache.get(`${scene.id}|${precision}`) ?? null,
      measure: (scene, precision) => {
        const job = deferred();
        measurements.push({ scene, precision, ...job });
        return job.promise;
      },
      probe: () => null,
    },
    benchmark: (options) => {
      const job = deferred();
      benchmarks.push({ options, ...job });
      return job.promise;
    },
    storage: { load: () => stored, save: (results) => saved.push(results) },
    hooks: {
      invalidate: () => events.push(['invalidate']),
      useEmulation: () => events.push(['useEmulation']),
      running: (running) => events.push(['running', running]),
      progress: (fraction, label) => events.push(['progress', fraction, label]),
      status: (end) => events.push(['status', end]),
    },
    now: () => clock,
  });
  return {
    runs,
    /** What the view shows for the values now (the runs' state, through words.js). */
    show: () => speedAccuracyView(values, runs.update()),
    values, events, measurements, cache, benchmarks, saved, advance: (ms) => { clock += ms; },
  };
}

// The first recommendation emulates every method over the scene's domain (seconds on a busy
// machine); later ones reuse it.
beforeAll(() => { setup().show(); }, 60_000);

describe('speed-accuracy runs: costs', () => {
  it('shows static counts without a run, and the session\'s results when there are some', () => {
    const fresh = setup().show();
    expect(fresh.mode).toBe('static');
    expect(fresh.device).toBe('No benchmark run yet on this device: the costs are static instruction counts.');
    expect(fresh.advice.criterionText).toContain('Costs: static instruction counts until you run the benchmark.');
    const stored = timedResults();
    const { runs, show } = setup({ stored });
    const view = show();
    expect(runs.results).toBe(stored);
    expect(view.mode).toBe('gpu');
    for (const row of view.rows) expect(row.x).toBe(10 + METHODS.findIndex((m) => m.id === row.methodId));
    expect(view.table.costHeader).toBe('Cost (GPU ns/eval)');
    expect(view.device).toContain('on Stand-in GPU');
    expect(view.rows.find((r) => r.methodId === 'exact-cg').costText).toBe('10.00 ns [9.00, 11.00]');
  });

  it('marks the Pareto front and the recommendation in the rows and the chart alike', () => {
    const view = setup({ stored: timedResults() }).show();
    expect(view.rows.filter((r) => r.recommended)).toEqual([view.chosen]);
    expect(view.chart.points.map((p) => p.id)).toEqual(view.rows.map((r) => r.methodId));
    view.rows.forEach((r, i) => expect(r.onFront).toBe(view.chart.front.includes(i)));
    expect(view.chart.front.length).toBeGreaterThan(0);
  });
});

describe('speed-accuracy runs: the benchmark', () => {
  it('runs once at a time, reports progress, keeps and saves the results and says how long it took', async () => {
    const {
      runs, show, events, benchmarks, saved, advance,
    } = setup();
    const run = runs.run('tiny');
    expect(runs.run('tiny')).toBe(run); // a second press joins the run under way
    await flush();
    expect(benchmarks).toHaveLength(1);
    expect(benchmarks[0].options.size).toBe('tiny');
    benchmarks[0].options.onProgress(0.25, 'Timing every method on this GPU…');
    const results = timedResults();
    advance(2460);
    benchmarks[0].resolve(results);
    await expect(run).resolves.toBe(results);
    expect(runs.results).toBe(results);
    expect(saved).toEqual([results]);
    expect(events).toEqual([
      ['running', true], ['progress', 0.25, 'Timing every method on this GPU…'], ['status', { done: 2460 }], ['invalidate'],
      ['running', false],
    ]);
    expect(show().mode).toBe('gpu');
    runs.run('tiny').catch(() => {});
    await flush();
    expect(benchmarks).toHaveLength(2); // after the end a new run starts
  });

  it('cancels: the run rejects, says so, and a result that still arrives is dropped', async () => {
    const { runs, events, benchmarks, saved } = setup();
    const run = runs.run('normal');
    const outcome = run.then(() => 'done', (error) => error.message);
    await flush();
    runs.cancel();
    expect(benchmarks[0].options.signal.aborted).toBe(true);
    benchmarks[0].resolve(timedResults()); // a runner that ignored the signal
    expect(await outcome).toBe('Benchmark cancelled');
    expect(runs.results).toBeNull();
    expect(saved).toEqual([]);
    expect(events.slice(-2)).toEqual([['status', { cancelled: true }], ['running', false]]);
  });

  it('tells the view why a run failed', async () => {
    const { runs, events, benchmarks } = setup();
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    const run = runs.run('normal').catch((error) => error.message);
    await flush();
    const refusal = new Error('the worker refused');
    benchmarks[0].reject(refusal);
    expect(await run).toBe('the worker refused');
    expect(events).toContainEqual(['status', { failed: refusal }]);
    expect(warn).toHaveBeenCalledOnce();
    warn.mockRestore();
  });

  it('dispose aborts a run and tells the view nothing more', async () => {
    const { runs, events, benchmarks } = setup();
    const run = runs.run('normal').catch((error) => error.name);
    await flush();
    events.length = 0;
    runs.dispose();
    expect(benchmarks[0].options.signal.aborted).toBe(true);
    benchmarks[0].options.onProgress(0.5, 'late');
    benchmarks[0].resolve(timedResults());
    expect(await run).toBe('AbortError');
    expect(events).toEqual([]);
    expect(runs.results).toBeNull();
  });
});

describe('speed-accuracy runs: errors read back from the GPU', () => {
  it('starts one read-back, says it is measuring, then plots the GPU\'s errors', async () => {
    const {
      runs, show, values, events, measurements, cache,
    } = setup();
    values.errors = 'gpu-highp';
    const waiting = show();
    show();
    expect(measurements).toHaveLength(1);
    expect(measurements[0].precision).toBe('highp');
    expect(waiting.source).toBe('js');
    expect(waiting.sourceLine).toEqual({
      text: 'Measuring the errors on this GPU in highp… The chart shows the JavaScript emulation until the read-back is done.',
      warning: false,
    });
    expect(runs.measurement).toBeInstanceOf(Promise);
    const plastic = sceneById('plastic');
    const measured = readBackOf(plastic);
    cache.set('plastic|highp', measured);
    measurements[0].resolve(measured);
    await runs.measurement;
    expect(events).toEqual([['invalidate']]);
    expect(runs.measurement).toBeNull();
    const view = show();
    expect(view.source).toBe('gpu-highp');
    for (const row of view.rows) expect(row.max).toBe(measured.errors[row.methodId].max);
    expect(view.advice.reasonText).toContain('this GPU in highp (read back)');
    expect(viewCsv(view).filename).toBe('speed-accuracy-plastic-gpu-highp.csv');
    expect(describeView(view, null)).toContain('with errors measured on this GPU in highp');
  });

  it('drops a read-back that another scene made stale', async () => {
    const {
      runs, show, values, events, measurements,
    } = setup();
    values.errors = 'gpu-highp';
    show();
    values.scene = 'metal';
    show();
    expect(measurements.map((m) => m.scene.id)).toEqual(['plastic', 'metal']);
    measurements[0].reject(new GpuFloatUnavailable('This GPU cannot render to float32 textures (no EXT_color_buffer_float).'));
    await flush();
    expect(events).toEqual([]);
    expect(runs.readBackError).toBeNull();
    expect(show().sourceLine.text).toMatch(/^Measuring the errors on this GPU in highp/);
  });

  it('words a refused shader as a refused shader, not as missing float targets, and falls back to the emulation', async () => {
    const {
      runs, show, values, events, measurements,
    } = setup();
    values.errors = 'gpu-mediump';
    show();
    const log = 'ERROR: 0:12: \'fm_evaluate\' : no matching overloaded function found\n';
    const refusal = new ShaderError({ stage: 'fragment', log, source: '' });
    const logged = vi.spyOn(console, 'error').mockImplementation(() => {});
    measurements[0].reject(refusal);
    await flush();
    expect(logged).toHaveBeenCalledWith(refusal); // the whole log, with the source lines it names
    logged.mockRestore();
    expect(events).toEqual([['useEmulation']]);
    expect(runs.readBackError).toBe(refusal);
    values.errors = 'js'; // what useEmulation does through the host
    expect(show().sourceLine).toEqual({
      text: 'This GPU could not compile the shader that evaluates a method, so the errors shown are the JavaScript '
        + 'emulation. The driver said: ERROR: 0:12: \'fm_evaluate\' : no matching overloaded function found',
      warning: true,
    });
    values.errors = 'gpu-highp'; // chosen again: the notice goes, a new read-back starts
    expect(show().sourceLine.warning).toBe(false);
  });

  it('dispose drops a read-back under way', async () => {
    const {
      runs, show, values, events, measurements,
    } = setup();
    values.errors = 'gpu-highp';
    show();
    runs.dispose();
    measurements[0].resolve(readBackOf(sceneById('plastic')));
    await flush();
    expect(events).toEqual([]);
  });
});

describe('statusText', () => {
  it('says how a benchmark ended', () => {
    expect(statusText({ done: 2460 })).toBe('Done in 2.5 s');
    expect(statusText({ cancelled: true })).toBe('Cancelled');
    expect(statusText({ failed: new Error('the worker refused') })).toBe('Benchmark failed: the worker refused');
  });
});

describe('readBackProblem', () => {
  it('names each cause in its own words', () => {
    const float = readBackProblem(new GpuFloatUnavailable('This GPU cannot render to float32 textures (no EXT_color_buffer_float).'));
    expect(float).toBe('This GPU cannot render to float32 textures (no EXT_color_buffer_float). Reading errors back needs WebGL2 with '
      + 'float render targets, so the errors shown are the JavaScript emulation.');
    expect(readBackProblem(new WebGL2Unavailable('This browser has no WebGL2.'))).toMatch(/^This browser has no WebGL2\. Reading/);
    expect(readBackProblem(new ShaderError({ stage: 'link', log: '' }))).toBe(
      'This GPU could not link the shader that evaluates a method, so the errors shown are the JavaScript emulation.',
    );
    expect(readBackProblem(new Error('the WebGL context was lost'))).toBe(
      'Reading the errors back from this GPU failed (the WebGL context was lost), so the errors shown are the JavaScript emulation.',
    );
  });
});

describe('speed-accuracy numbers', () => {
  it('writes codes and timings with a real minus sign', () => {
    expect(formatCodes(0.00012)).toBe(`1.2e${MINUS}4`);
    expect(formatCodes(3.14159)).toBe('3.14');
    expect(formatCodes(12.07)).toBe('12.1');
    expect(formatCodes(NaN)).toBe('NaN/∞');
    expect(formatCodes(0)).toBe('0');
    expect(formatNs({ median: -0.42, min: -3.5, max: 250 })).toBe(`${MINUS}0.42 ns [${MINUS}3.50, 250]`);
    expect(formatNs({ median: NaN, min: 0, max: 0 })).toBe('–');
    expect(shortDecimal(1 / 1.5)).toBe('0.667');
    expect(shortDecimal(1.5)).toBe('1.5');
    expect(shortDecimal(2)).toBe('2');
  });
});
