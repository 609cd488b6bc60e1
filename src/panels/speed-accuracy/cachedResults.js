// @ts-check
// The benchmark's results kept for the session (sessionStorage), read back as untrusted text: an
// older page may have written another shape, and anyone can edit storage. Only measurements are
// taken from it, each checked for its type; what the code computes (the errors in JS emulation,
// the recommendations) is computed again, so a stored claim never reaches the panel.
import { benchResults, RESULTS_VERSION } from '../../methods/benchResults.js';
import { METHODS } from '../../methods/methods.js';
import { own } from '../../host/own.js';

const MAX_SAMPLES = 1000;

/** @typedef {import('../../methods/benchResults.js').Spread} Spread */
/** @typedef {import('../../methods/benchResults.js').Timing} Timing */
/** @typedef {import('../../methods/benchResults.js').FramePart} FramePart */
/** @typedef {import('../../methods/benchResults.js').BenchRun} BenchRun */

/** @type {(v: unknown) => string | null} */
const text = (v) => (typeof v === 'string' ? v.slice(0, 300) : null);
/** @type {(v: unknown) => v is number} */
const finite = (v) => typeof v === 'number' && Number.isFinite(v);
/** A measurement that may have been too large to count (an error of ∞ where a method gave NaN). @type {(v: unknown) => v is number} */
const measure = (v) => finite(v) || v === Infinity;

/**
 * { median, min, max } of finite numbers, else undefined. A time may be below 0: a method's time is
 * its pass's less the baseline pass's, and on a fast or software GPU the two are within noise.
 * @param {unknown} v
 * @returns {Spread | undefined}
 */
function stats(v) {
  const [median, min, max] = [own(v, 'median'), own(v, 'min'), own(v, 'max')];
  return finite(median) && finite(min) && finite(max) ? { median, min, max } : undefined;
}

/** @type {(v: unknown) => number[]} */
const samples = (v) => (Array.isArray(v) && v.length <= MAX_SAMPLES && v.every(finite) ? v : []);

/**
 * One method's timing ({ nsPerEval, samples }) as timeMethods* gave it, or undefined.
 * @param {unknown} v
 * @returns {Timing | undefined}
 */
function timing(v) {
  const nsPerEval = stats(own(v, 'nsPerEval'));
  return nsPerEval ? { nsPerEval, samples: samples(own(v, 'samples')) } : undefined;
}

/**
 * An error summary read back from the GPU, or undefined: each a number or ∞, θ of the largest also null, the NaN count finite.
 * @param {unknown} v
 * @returns {import('../../methods/benchResults.js').ErrorSummary | undefined}
 */
function gpuError(v) {
  const [max, mean, rms, maxCodes, thetaAtMaxDeg, nanCount] = ['max', 'mean', 'rms', 'maxCodes', 'thetaAtMaxDeg', 'nanCount']
    .map((k) => own(v, k));
  if (!(measure(max) && measure(mean) && measure(rms) && measure(maxCodes) && (thetaAtMaxDeg === null || measure(thetaAtMaxDeg))
    && finite(nanCount))) return undefined;
  return { max, mean, rms, maxCodes, thetaAtMaxDeg: measure(thetaAtMaxDeg) ? thetaAtMaxDeg : null, nanCount };
}

/**
 * The results in `raw` (the stored JSON text), rebuilt through benchResults from the measurements
 * it holds, or null when it is not this version's results. A measurement of the wrong type is
 * left out, as a run that did not measure it.
 * @param {unknown} raw
 * @returns {import('../../methods/benchResults.js').BenchResults | null}
 */
export function readCachedResults(raw) {
  /** @type {unknown} */
  let saved;
  try {
    saved = JSON.parse(typeof raw === 'string' ? raw : 'null');
  } catch {
    return null;
  }
  const rows = own(saved, 'methods');
  if (own(saved, 'version') !== RESULTS_VERSION || !Array.isArray(rows) || rows.length !== METHODS.length) return null;
  if (!METHODS.every((m, i) => own(rows[i], 'id') === m.id)) return null;
  /** @type {{ highp: Record<string, Timing>, mediump: Record<string, Timing> }} */
  const gpuResults = { highp: {}, mediump: {} };
  /** @type {{ methods: Record<string, Timing>, where: string }} */
  const cpu = { methods: {}, where: 'page' };
  /** @type {import('../../methods/benchResults.js').GpuErrors} */
  const gpuErrors = {};
  METHODS.forEach((m, i) => {
    const row = rows[i];
    const highp = timing(own(row, 'gpu'));
    const mediump = timing(own(own(row, 'gpu'), 'mediump'));
    if (highp) gpuResults.highp[m.id] = highp;
    if (mediump) gpuResults.mediump[m.id] = mediump;
    const onCpu = timing(own(row, 'cpu'));
    if (onCpu) cpu.methods[m.id] = onCpu;
    if (own(own(row, 'cpu'), 'where') === 'worker') cpu.where = 'worker';
    const error = own(row, 'error');
    const scene = own(error, 'scene');
    for (const [precision, key] of [['highp', 'gpuHighp'], ['mediump', 'gpuMediump']]) {
      const e = gpuError(own(error, key));
      if (!e || typeof scene !== 'string') continue;
      // methodErrors summarises errorsFromValues(); the summary carries θ in degrees already.
      const entry = { ...e, thetaAtMax: e.thetaAtMaxDeg === null ? null : (e.thetaAtMaxDeg * Math.PI) / 180 };
      ((gpuErrors[scene] ??= {})[precision] ??= {})[m.id] = entry;
    }
  });
  const device = own(saved, 'device');
  const run = own(own(saved, 'config'), 'gpu');
  /** @param {string} k */
  const runNumber = (k) => { const x = own(run, k); return finite(x) ? x : null; };
  const gpu = {
    results: gpuResults,
    device: { renderer: text(own(device, 'renderer')), vendor: text(own(device, 'vendor')), version: text(own(device, 'webgl')) },
    timer: text(own(device, 'timer')),
    size: runNumber('size'),
    loops: runNumber('loops'),
    passes: runNumber('passes'),
    bestOf: runNumber('bestOf'),
    repeats: runNumber('repeats'),
    evaluationsPerPass: runNumber('evaluationsPerPass'),
  };
  const hasGpu = Object.keys(gpu.results.highp).length + Object.keys(gpu.results.mediump).length > 0;
  const date = text(own(saved, 'date'));
  const results = benchResults({
    gpu: hasGpu ? gpu : null,
    cpu: Object.keys(cpu.methods).length ? cpu : null,
    frames: frames(own(saved, 'frames')),
    gpuErrors: Object.keys(gpuErrors).length ? gpuErrors : null,
    meta: {
      date: date && !Number.isNaN(Date.parse(date)) ? date : null,
      userAgent: text(own(device, 'userAgent')),
      gpuError: text(own(device, 'gpuError')),
      gpuReadbackError: text(own(device, 'gpuReadbackError')),
      device: gpu.device,
      config: { size: text(own(own(saved, 'config'), 'size')) },
    },
  });
  return results;
}

/**
 * A part of the frame timing ({ msPerFrame, pixels }), or null.
 * @param {unknown} s
 * @returns {FramePart | null}
 */
function framePart(s) {
  const msPerFrame = stats(own(s, 'msPerFrame'));
  const pixels = own(s, 'pixels');
  return msPerFrame && finite(pixels) ? { msPerFrame, pixels } : null;
}

/**
 * The frame timing of the hero against three.js, or null. The parts measured since the frame was
 * timed in parts (timeFrames.js) are kept only when all of them are there.
 * @param {unknown} v
 * @returns {BenchRun['frames']}
 */
function frames(v) {
  const spheres = framePart(own(v, 'spheres'));
  const threePhysical = framePart(own(v, 'threePhysical'));
  const [width, height, ratio] = ['width', 'height', 'ratio'].map((k) => own(v, k));
  if (!spheres || !threePhysical || !finite(width) || !finite(height) || !finite(ratio)) return null;
  const kept = { width, height, ratio, spheres: { ...spheres, timer: text(own(v, 'timer')) }, threePhysical };
  const [spheresView, spheresOnePass, copy, threePlain] = ['spheresView', 'spheresOnePass', 'copy', 'threePlain']
    .map((k) => framePart(own(v, k)));
  const plainRatio = own(v, 'plainRatio');
  return spheresView && spheresOnePass && copy && threePlain && finite(plainRatio)
    ? { ...kept, spheresView, spheresOnePass, copy, threePlain, plainRatio } : kept;
}
