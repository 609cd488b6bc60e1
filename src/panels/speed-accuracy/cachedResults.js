// The benchmark's results kept for the session (sessionStorage), read back as untrusted text: an
// older page may have written another shape, and anyone can edit storage. Only measurements are
// taken from it, each checked for its type; what the code computes (the errors in JS emulation,
// the recommendations) is computed again, so a stored claim never reaches the panel.
import { benchResults, RESULTS_VERSION } from '../../methods/benchResults.js';
import { METHODS } from '../../methods/methods.js';
import { own } from '../../host/own.js';

const MAX_SAMPLES = 1000;
const text = (v) => (typeof v === 'string' ? v.slice(0, 300) : null);
const finite = (v) => typeof v === 'number' && Number.isFinite(v);

/**
 * { median, min, max } of finite numbers, else undefined. A time may be below 0: a method's time is
 * its pass's less the baseline pass's, and on a fast or software GPU the two are within noise.
 */
function stats(v) {
  const s = { median: own(v, 'median'), min: own(v, 'min'), max: own(v, 'max') };
  return Object.values(s).every(finite) ? s : undefined;
}

const samples = (v) => (Array.isArray(v) && v.length <= MAX_SAMPLES && v.every(finite) ? v : []);

/** One method's timing ({ nsPerEval, samples }) as timeMethods* gave it, or undefined. */
function timing(v) {
  const nsPerEval = stats(own(v, 'nsPerEval'));
  return nsPerEval ? { nsPerEval, samples: samples(own(v, 'samples')) } : undefined;
}

/** An error summary read back from the GPU, or undefined. */
function gpuError(v) {
  const fields = ['max', 'mean', 'rms', 'maxCodes', 'thetaAtMaxDeg', 'nanCount'].map((k) => [k, own(v, k)]);
  const ok = fields.every(([k, x]) => finite(x) || (k === 'thetaAtMaxDeg' && x === null) || (k !== 'nanCount' && x === Infinity));
  return ok ? Object.fromEntries(fields) : undefined;
}

/**
 * The results in `raw` (the stored JSON text), rebuilt through benchResults from the measurements
 * it holds, or null when it is not this version's results. A measurement of the wrong type is
 * left out, as a run that did not measure it.
 */
export function readCachedResults(raw) {
  let saved;
  try {
    saved = JSON.parse(typeof raw === 'string' ? raw : 'null');
  } catch {
    return null;
  }
  const rows = own(saved, 'methods');
  if (own(saved, 'version') !== RESULTS_VERSION || !Array.isArray(rows) || rows.length !== METHODS.length) return null;
  if (!METHODS.every((m, i) => own(rows[i], 'id') === m.id)) return null;
  const gpu = /** @type {any} */ ({ results: { highp: {}, mediump: {} }, device: {}, timer: null });
  const cpu = { methods: {}, where: 'page' };
  const gpuErrors = {};
  METHODS.forEach((m, i) => {
    const row = rows[i];
    const highp = timing(own(row, 'gpu'));
    const mediump = timing(own(own(row, 'gpu'), 'mediump'));
    if (highp) gpu.results.highp[m.id] = highp;
    if (mediump) gpu.results.mediump[m.id] = mediump;
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
  gpu.device = { renderer: text(own(device, 'renderer')), vendor: text(own(device, 'vendor')), version: text(own(device, 'webgl')) };
  gpu.timer = text(own(device, 'timer'));
  const run = own(own(saved, 'config'), 'gpu');
  for (const k of ['size', 'loops', 'passes', 'bestOf', 'repeats', 'evaluationsPerPass']) gpu[k] = finite(own(run, k)) ? run[k] : null;
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
 * The frame timing of the hero against three.js, or null. The parts measured since the frame was
 * timed in parts (timeFrames.js) are kept only when all of them are there.
 */
function frames(v) {
  const side = (s) => {
    const msPerFrame = stats(own(s, 'msPerFrame'));
    return msPerFrame && finite(own(s, 'pixels')) ? { msPerFrame, pixels: s.pixels } : null;
  };
  const spheres = side(own(v, 'spheres'));
  const threePhysical = side(own(v, 'threePhysical'));
  const [width, height, ratio] = ['width', 'height', 'ratio'].map((k) => own(v, k));
  if (!spheres || !threePhysical || ![width, height, ratio].every(finite)) return null;
  const kept = { width, height, ratio, spheres: { ...spheres, timer: text(own(v, 'timer')) }, threePhysical };
  const parts = Object.fromEntries(['spheresView', 'spheresOnePass', 'copy', 'threePlain'].map((k) => [k, side(own(v, k))]));
  const plainRatio = own(v, 'plainRatio');
  return Object.values(parts).every(Boolean) && finite(plainRatio) ? { ...kept, ...parts, plainRatio } : kept;
}
