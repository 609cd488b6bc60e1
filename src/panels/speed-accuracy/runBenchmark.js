// @ts-check
// "Run benchmark": GPU cost per method (timeMethodsGpu), the GPU's own errors over the default
// domains in highp and mediump (read back, measureGpuErrors.js), CPU cost per method
// (timeMethodsCpu, in a worker: timeCpu.js), and the hero's frame cost against three.js MeshPhysicalMaterial, one after the
// other on the viewer's device, with progress and cancel; results kept for the session
// (sessionStorage).
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { createContext } from '../../gl/createContext.js';
import { deviceInfo, timeMethodsGpu } from '../../gl/timeMethodsGpu.js';
import { benchResults, DEFAULT_DOMAIN, GPU_ERROR_KEYS } from '../../methods/benchResults.js';
import { sceneById } from '../../methods/scenes.js';
import { timeCpu } from './timeCpu.js';
import { readCachedResults } from './cachedResults.js';
import { timeFrames } from './timeFrames.js';
import { gpuErrorsOn, rememberGpuErrors } from './measureGpuErrors.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

/** Run sizes: 'normal' takes a few seconds on a GPU (longer on SwiftShader); 'tiny' is for tests. */
export const BENCH_SIZES = Object.freeze({
  normal: {
    gpu: { size: 128, loops: 16, targetMs: 5, passes: 2, bestOf: 3, repeats: 5 },
    cpu: { repeats: 5, minMs: 15, count: 2048 },
    frames: { width: 900, height: 300, frames: 12, warmup: 3 },
  },
  tiny: {
    gpu: { size: 8, loops: 2, targetMs: 1, passes: 1, bestOf: 2, repeats: 2 },
    cpu: { repeats: 2, minMs: 1, count: 128 },
    frames: { width: 150, height: 50, frames: 3, warmup: 1 },
  },
});

/** @typedef {'gpu' | 'errors' | 'cpu' | 'frames'} Phase */
/** @type {Record<Phase, [number, number]>} share of the progress bar */
const PHASES = { gpu: [0, 0.5], errors: [0.5, 0.6], cpu: [0.6, 0.8], frames: [0.8, 1] };
// What the progress line says during a phase whose steps carry no label of their own.
const PHASE_WORDS = { gpu: 'phaseGpu', errors: 'phaseErrors', cpu: 'phaseCpu', frames: 'phaseFrames' };
const CACHE_KEY = 'fresnel-lab:speed-accuracy:results';

/** @typedef {import('../../methods/benchResults.js').BenchRun} BenchRun */
/** @typedef {import('../../methods/benchResults.js').BenchResults} BenchResults */

// What was thrown, read with `in`: an Error's or a DOMException's name and message are its prototype's.
/** @param {unknown} error */
const isAbort = (error) => typeof error === 'object' && error !== null && 'name' in error && error.name === 'AbortError';
/** What a failure says: its message, else itself in words. @param {unknown} error */
const messageOf = (error) => String((typeof error === 'object' && error !== null && 'message' in error ? error.message : null) ?? error);

/** @type {(size: string) => size is keyof typeof BENCH_SIZES} */
export const isBenchSize = (size) => Object.hasOwn(BENCH_SIZES, size);

/**
 * Runs every measurement. host: a laid-out element for the frame-timing canvases. Options:
 * size ('normal' | 'tiny'), onProgress(fraction, label), signal (AbortSignal), whenVisible (a
 * promise between steps: the run waits there while its panel is off screen). Resolves to
 * benchResults(); without WebGL2 the GPU and frame parts are null and the CPU is still timed;
 * a GPU timing that fails (a shader the driver rejects) is reported in device.gpuError, a read-back
 * that fails (no float render targets) in device.gpuReadbackError.
 * @param {HTMLElement} host
 * @param {{ size?: string, onProgress?: (fraction: number, label: string) => void, signal?: AbortSignal,
 *   whenVisible?: () => Promise<void> }} [options]
 */
export async function runBenchmark(host, { size = 'normal', onProgress, signal, whenVisible } = {}) {
  if (!isBenchSize(size)) throw new RangeError(`unknown benchmark size ${size}`);
  const config = BENCH_SIZES[size];
  /** @type {(phase: Phase) => (done: number, total: number, label?: string) => void} */
  const report = (phase) => (done, total, label) => {
    const [a, b] = PHASES[phase];
    onProgress?.(a + ((b - a) * done) / Math.max(1, total), label ?? t(PHASE_WORDS[phase]));
  };
  /** @type {BenchRun['gpu']} */
  let gpu = null;
  /** @type {string | null} */
  let gpuError = null;
  /** @type {BenchRun['gpuErrors']} */
  let gpuErrors = null;
  /** @type {string | null} */
  let gpuReadbackError = null;
  /** @type {BenchRun['frames']} */
  let frames = null;
  /** @type {ReturnType<typeof createContext> | null} */
  let context = null;
  /** @type {ReturnType<typeof deviceInfo> | null} */
  let device = null;
  try {
    context = createContext(document.createElement('canvas'));
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
  }
  try {
    if (context) {
      device = deviceInfo(context.gl);
      try {
        onProgress?.(0, t('compilingTimers'));
        gpu = await timeMethodsGpu(context.gl, { ...config.gpu, signal, whenVisible, onProgress: report('gpu') });
      } catch (error) {
        // A shader this GPU cannot compile must not hide the other numbers: say so instead.
        if (isAbort(error)) throw error;
        gpuError = messageOf(error);
      }
      try {
        // The errors the GPU itself makes over the default domains, on the same context.
        const scenes = [...new Set(Object.values(DEFAULT_DOMAIN))].map(sceneById);
        const options = { signal, whenVisible, onProgress: report('errors') };
        const readBack = await gpuErrorsOn(context.gl, scenes, Object.keys(GPU_ERROR_KEYS), options);
        gpuErrors = readBack.errors;
        rememberGpuErrors(readBack); // the panel's "Error measured by" needs no second read-back
      } catch (error) {
        if (isAbort(error)) throw error;
        gpuReadbackError = messageOf(error);
      }
    }
  } finally {
    context?.dispose();
  }
  await whenVisible?.();
  const cpu = await timeCpu({ ...config.cpu, signal, onProgress: report('cpu') });
  if (context) frames = await timeFrames(host, { ...config.frames, signal, whenVisible, onProgress: report('frames') });
  onProgress?.(1, t('done'));
  return benchResults({
    gpu, cpu, frames, gpuErrors,
    meta: { date: new Date().toISOString(), userAgent: navigator.userAgent, config: { size }, gpuError, gpuReadbackError, device },
  });
}

/**
 * The results saved this session, or null (read as untrusted text: cachedResults.js).
 * @returns {BenchResults | null}
 */
export function loadCachedResults() {
  try {
    return readCachedResults(sessionStorage.getItem(CACHE_KEY));
  } catch {
    return null; // storage refused
  }
}

/** @param {BenchResults} results */
export function saveCachedResults(results) {
  try {
    sessionStorage.setItem(CACHE_KEY, JSON.stringify(results));
  } catch {
    // Storage blocked or full: the results still show until the page is left.
  }
}
