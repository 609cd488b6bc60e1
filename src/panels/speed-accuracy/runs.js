// @ts-check
// The state and the runs of the speed-accuracy panel, apart from its DOM: the benchmark's results
// (kept for the session), a benchmark under way, the GPU read-back of a scene's errors and the
// error that stopped it. index.js shows what they hold through words.js (speedAccuracyView), which
// also words the causes these runs keep as data. Both runs go stale through run gates: the
// benchmark when it is cancelled or the panel disposed, a read-back when another scene or
// precision is asked for or the panel disposed, so a late result is dropped.
import { benchResults } from '../../methods/benchResults.js';
import { sceneById } from '../../methods/scenes.js';
import { ShaderError } from '../../gl/shaderError.js';
import { createRunGate, isStaleRun } from '../shared/createRunGate.js';
import { glslOf } from './glslOf.js';

/** @typedef {import('../../methods/scenes.js').Scene} Scene */
/** @typedef {import('../../methods/benchResults.js').BenchResults} BenchResults */

/**
 * What mediump and highp are on this GPU: the bits each keeps, measured (evaluateMethodsGpu probePrecision), what the
 * driver claims (gpuPrecisionInfo), and the device (deviceInfo).
 * @typedef {{ probe: { highpBits: number, mediumpBits: number, mediumpIsFullPrecision: boolean },
 *   claimed: Record<'highp' | 'mediump', { rangeMin: number, rangeMax: number, precision: number } | null>,
 *   device: { renderer: string, vendor: string, version: string } }} GpuProbe
 */

/**
 * A scene's errors read back from the GPU in one GLSL precision, by method id (gpuErrors.errorsFromValues), with the probe.
 * @typedef {GpuProbe & { errors: Record<string, import('../../methods/advisor.js').MethodError> }} GpuMeasurement
 */

/**
 * The GPU read-back as the runs use it (measureGpuErrors.js), so a stand-in can take its place.
 * @typedef {object} ReadBack
 * @property {(scene: Scene, precision: string) => GpuMeasurement | null} cached  the session's measurement, or null
 * @property {(scene: Scene, precision: string) => Promise<GpuMeasurement>} measure  measures (once per session)
 * @property {() => GpuProbe | null} probe  what mediump is on this GPU, once anything was measured (or null)
 */

/**
 * The errors to plot: the source chosen ('js', 'gpu-highp', 'gpu-mediump'), the GLSL precision of the read-back (null for
 * the JS emulation), the GPU's errors (null for the JS emulation) and the precision being read back (or null).
 * @typedef {{ source: string, glsl: string | null, measured: GpuMeasurement | null, waiting: string | null }} ErrorSource
 */

/**
 * How the last benchmark ended, for the status line (words.js statusText): done in `ms`, cancelled,
 * or failed with `error`.
 * @typedef {{ done: number } | { cancelled: true } | { failed: unknown }} BenchmarkEnd
 */

/**
 * What the words need of the runs, at each update: the errors to plot ({ source, glsl, measured,
 * waiting }), the benchmark's results (or null), why the GPU read-back failed (the error, or null)
 * and what mediump is on this GPU (or null).
 * @typedef {{ source: ErrorSource, results: BenchResults | null, readBackError: unknown, probe: GpuProbe | null }} SpeedAccuracyState
 */

/**
 * What the view does when the state changes.
 * @typedef {object} SpeedAccuracyHooks
 * @property {() => void} invalidate  a result arrived: draw and describe again
 * @property {() => void} useEmulation  the read-back cannot be had here: set the error source to the JS emulation
 * @property {(running: boolean) => void} running  a benchmark started or ended
 * @property {(fraction: number, label: string) => void} progress  the benchmark's progress
 * @property {(end: BenchmarkEnd) => void} status  a benchmark ended (the status line says how)
 */

/**
 * @param {{
 *   values: import('../../host/panelContract.js').ValuesOf<typeof import('./schema.js').schema>,
 *   readBack: ReadBack,
 *   benchmark: (options: { size: string, signal: AbortSignal, onProgress: (fraction: number, label: string) => void }) =>
 *     Promise<BenchResults>,
 *   storage: { load: () => BenchResults | null, save: (results: BenchResults) => void },
 *   hooks: SpeedAccuracyHooks,
 *   now?: () => number,
 * }} options  values: the host's live values; benchmark: runBenchmark on the panel's stage; storage: the session's results
 */
export function createSpeedAccuracyRuns({
  values, readBack, benchmark, storage, hooks, now = () => performance.now(),
}) {
  const benchGate = createRunGate();
  const readGate = createRunGate();
  let results = storage.load();
  /** @type {Promise<BenchResults> | null} */
  let running = null;
  /** @type {{ key: string, promise: Promise<void> } | null} the GPU read-back under way */
  let measuring = null;
  /** @type {unknown} why the GPU read-back failed here, once it has (null while it has not) */
  let readBackError = null;
  let disposed = false;

  /**
   * Starts reading a scene's errors back from the GPU (once per scene and precision per session).
   * @param {Scene} scene
   * @param {string} glsl
   */
  function startMeasuring(scene, glsl) {
    const key = `${scene.id}|${glsl}`;
    if (measuring?.key === key) return;
    const run = readGate.begin();
    const promise = readBack.measure(scene, glsl).then(() => {
      if (!run.live) return; // another scene or precision was asked for meanwhile, or the panel is gone
      measuring = null;
      readBackError = null;
      hooks.invalidate();
    }, (error) => {
      if (!run.live) return;
      measuring = null;
      if (error instanceof ShaderError) console.error(error); // the whole log, for whoever reports it
      readBackError = error;
      if (glslOf(values.errors)) hooks.useEmulation();
      else hooks.invalidate();
    });
    measuring = { key, promise };
  }

  /**
   * The errors to plot: { source, glsl, measured (the GPU's, or null for JS), waiting }.
   * @param {Scene} scene
   * @returns {ErrorSource}
   */
  function errorSource(scene) {
    const glsl = glslOf(values.errors);
    if (!glsl) return { source: 'js', glsl: null, measured: null, waiting: null };
    const measured = readBack.cached(scene, glsl);
    if (measured) return { source: values.errors, glsl, measured, waiting: null };
    startMeasuring(scene, glsl);
    return { source: 'js', glsl: null, measured: null, waiting: glsl };
  }

  async function runOnce(/** @type {string} */ size) {
    const run = benchGate.begin();
    hooks.running(true);
    const started = now();
    await null; // run() keeps this promise as the one under way before anything below can end it
    try {
      /** @type {(fraction: number, label: string) => void} */
      const onProgress = (fraction, label) => { if (run.live) hooks.progress(fraction, label); };
      const next = await benchmark({ size, signal: run.signal, onProgress });
      run.throwIfStale(); // cancelled as it ended: dropped as any cancelled run
      results = next;
      storage.save(next);
      hooks.status({ done: now() - started });
      hooks.invalidate(); // redraws and refreshes the description
      return next;
    } catch (error) {
      const stale = isStaleRun(error);
      if (!disposed) hooks.status(stale ? { cancelled: true } : { failed: error });
      if (!stale) console.warn(error);
      throw error;
    } finally {
      if (!disposed) hooks.running(false);
      running = null;
    }
  }

  return {
    /** The benchmark's results (this run's or the session's), or null. */
    get results() { return results; },
    /** The GPU read-back under way, or null. */
    get measurement() { return measuring?.promise ?? null; },
    /** Why the GPU read-back failed here (the error; null when it has not). */
    get readBackError() { return readBackError; },
    /**
     * What the words need for the values (starting the GPU read-back they ask for, if it is not there yet).
     * @returns {SpeedAccuracyState}
     */
    update() {
      const source = errorSource(sceneById(values.scene));
      return { source, results, readBackError, probe: readBack.probe() };
    },
    /** Runs the benchmark at a size of BENCH_SIZES; while one runs, the same run. Rejects when it is cancelled. */
    run(/** @type {string} */ size) {
      running ??= runOnce(size);
      return running;
    },
    cancel() { benchGate.cancel('Benchmark cancelled'); },
    /** Results to export: the last run, or errors and static costs only. */
    currentResults() { return results ?? benchResults({ meta: { date: new Date().toISOString() } }); },
    dispose() {
      disposed = true;
      benchGate.dispose();
      readGate.dispose();
    },
  };
}
