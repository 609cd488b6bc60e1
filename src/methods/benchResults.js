// The benchmark's results as data: one object for bench/results.json and the panel's JSON
// export, the same numbers as CSV columns and as a text table. Costs come from a run
// (timeMethodsGpu, timeMethodsCpu, the frame timing); errors are computed here, against the
// float64 reference, over each method kind's default domain (scenes.js: opaque plastic for
// dielectrics, gold and aluminium for conductors), in float64, float32 and float16 emulation,
// and, when the run read them back, on the GPU in highp and mediump (gpuErrors.js).
import { methodError } from './advisor.js';
import { recommendWithin } from './displayBudgets.js';
import { METHODS } from './methods.js';
import { PRECISION_IDS } from './rounding.js';
import { SCENES, sceneById } from './scenes.js';
import { toDegrees } from '../optics/angles.js';
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';

const t = messages('methods', english);

/** A timing's median and spread. @typedef {{ median: number, min: number, max: number }} Spread */
/** One method's timing: ns per evaluation, and the samples. @typedef {{ nsPerEval: Spread, samples: number[] }} Timing */
/**
 * An error as the results keep it (summary()): θ of the largest in degrees.
 * @typedef {{ max: number, mean: number, rms: number, maxCodes: number, thetaAtMaxDeg: number | null, nanCount: number }} ErrorSummary
 */
/**
 * A method's errors over its kind's default domain (methodErrors()).
 * @typedef {{ scene: string, weighting: string, fp64: ErrorSummary, fp32: ErrorSummary, fp16: ErrorSummary,
 *   gpuHighp: ErrorSummary | null, gpuMediump: ErrorSummary | null }} MethodErrors
 */
/** A part of the frame timing: ms per frame and the pixels drawn. @typedef {{ msPerFrame: Spread, pixels: number }} FramePart */
/**
 * The frame timing (timeFrames.js) as the results keep it: the hero after a change of n (spheres) and the clear-coated
 * peer (threePhysical) always; the other parts in results measured since the frame was timed in parts.
 * @typedef {{ width: number, height: number, timer: string | null, ratio: number, plainRatio?: number,
 *   spheres: FramePart, threePhysical: FramePart, spheresView?: FramePart, spheresOnePass?: FramePart, copy?: FramePart,
 *   threePlain?: FramePart }} FrameResults
 */
/**
 * One method's row of the results.
 * @typedef {{ id: string, label: string, kind: 'dielectric' | 'conductor', staticCost: number,
 *   gpu: { precision: 'highp', nsPerEval: Spread | null, samples: number[], mediump: Timing | null } | null,
 *   cpu: { context: 'fp64', where: string, nsPerEval: Spread, samples: number[] } | null,
 *   error: MethodErrors }} MethodResults
 */
/** @typedef {{ methodId: string, invisible: boolean, budgetCodes: number, reason: string }} Pick */
/**
 * The results object (bench/results.json, the panel's JSON export and its session store).
 * @typedef {object} BenchResults
 * @property {number} version  RESULTS_VERSION
 * @property {string | null} date  ISO 8601
 * @property {{ renderer: string | null, vendor: string | null, webgl: string | null, timer: string | null,
 *   gpuError: string | null, gpuReadbackError: string | null, userAgent: string | null }} device
 * @property {{ size?: string | null, gpu: GpuRunConfig | null }} config
 * @property {MethodResults[]} methods  one per method of METHODS, in its order
 * @property {FrameResults | null} frames
 * @property {Record<string, { costSource: string, invisible: Pick, acceptable: Pick }>} recommendations  by scene id
 */
/**
 * How the GPU was timed. @typedef {{ size: number | null, loops: number | null, passes: number | null, bestOf: number | null,
 *   repeats: number | null, evaluationsPerPass: number | null }} GpuRunConfig
 */
/**
 * The errors read back on the GPU, by scene, GLSL precision and method: errorsFromValues(), of which the results keep
 * these fields.
 * @typedef {Record<string, Record<string, Record<string, Pick<import('./advisor.js').MethodError,
 *   'max' | 'mean' | 'rms' | 'maxCodes' | 'thetaAtMax' | 'nanCount'>>>>} GpuErrors
 */
/**
 * timeMethodsGpu's result: how it timed, the device, each method's timing by GLSL precision, the empty pass's time.
 * @typedef {{ timer: string, device: Device, size: number, loops: number, passes: number, bestOf: number, repeats: number,
 *   evaluationsPerPass: number, results: { highp: Record<string, Timing>, mediump: Record<string, Timing> },
 *   baselineMs: Spread }} GpuTimings
 */
/**
 * timeFrames' result: each part's time, the ratios of the hero to its peers, the size.
 * @typedef {{ width: number, height: number, ratio: number, plainRatio: number, spheres: FramePart & { timer: string | null },
 *   spheresView: FramePart, spheresOnePass: FramePart, copy: FramePart, threePhysical: FramePart, threePlain: FramePart }} FrameTimings
 */
/** The device's strings (deviceInfo). @typedef {{ renderer: string | null, vendor: string | null, version: string | null }} Device */
/**
 * What benchResults() is given. gpu: timeMethodsGpu's result; cpu: timeMethodsCpu's; frames: timeFrames'; gpuErrors:
 * the errors read back on the GPU (see methodErrors); meta.device: deviceInfo, for when the GPU timing failed.
 * @typedef {object} BenchRun
 * @property {(GpuRunConfig & { timer: string | null, device: Device,
 *   results: { highp: Record<string, Timing>, mediump: Record<string, Timing> } }) | null} [gpu]
 * @property {{ where?: string, methods: Record<string, Timing> } | null} [cpu]
 * @property {Omit<FrameResults, 'timer' | 'spheres'> & { spheres: FramePart & { timer?: string | null } } | null} [frames]
 * @property {GpuErrors | null} [gpuErrors]
 * @property {{ date?: string | null, userAgent?: string | null, config?: { size?: string | null }, gpuError?: string | null,
 *   gpuReadbackError?: string | null, device?: Device | null }} [meta]
 */

export const RESULTS_VERSION = 1;
export const DEFAULT_DOMAIN = Object.freeze({ dielectric: 'plastic', conductor: 'metal' });

/** GLSL precision that runs a scene precision: fp16 → mediump, fp32 or fp64 → highp. */
export function gpuPrecisionFor(precision) {
  return precision === 'fp16' ? 'mediump' : 'highp';
}

/** The fields of an error kept in the results. */
function summary(e) {
  return {
    max: e.max, mean: e.mean, rms: e.rms, maxCodes: e.maxCodes,
    thetaAtMaxDeg: e.thetaAtMax === null ? null : toDegrees(e.thetaAtMax), nanCount: e.nanCount,
  };
}

/** Result keys of the errors read back from the GPU, by GLSL precision. */
export const GPU_ERROR_KEYS = Object.freeze({ highp: 'gpuHighp', mediump: 'gpuMediump' });

/**
 * Error of a method over its kind's default domain: { scene, weighting, fp64, fp32, fp16,
 * gpuHighp, gpuMediump }, each { max, mean, rms, maxCodes, thetaAtMaxDeg, nanCount } (mean and
 * RMS weighted as the scene is). fp*: JS emulation; gpu*: from gpuErrors, the read-back errors
 * ({ [sceneId]: { highp, mediump: { [methodId]: errorsFromValues() } } }), null without them.
 */
export function methodErrors(method, gpuErrors = null) {
  const scene = sceneById(DEFAULT_DOMAIN[method.kind]);
  const out = { scene: scene.id, weighting: scene.weighting };
  for (const p of PRECISION_IDS) out[p] = summary(methodError(scene, method, p));
  for (const [precision, key] of Object.entries(GPU_ERROR_KEYS)) {
    const e = gpuErrors?.[scene.id]?.[precision]?.[method.id];
    out[key] = e ? summary(e) : null;
  }
  return out;
}

/**
 * Measured cost per method for a scene ({ id: ns }, medians), from a results object: the GPU at
 * the scene's precision, or at glslPrecision when given ('gpu'), or the CPU ('cpu'). {} when the
 * run has no finite value for every method of the scene's kind (advisor.recommend wants all or none).
 */
export function measuredCosts(results, scene, source = 'gpu', glslPrecision = gpuPrecisionFor(scene.precision)) {
  if (!results) return {};
  const costs = {};
  for (const row of results.methods.filter((m) => m.kind === scene.kind)) {
    const ns = source === 'cpu' ? row.cpu?.nsPerEval?.median
      : (glslPrecision === 'mediump' ? row.gpu?.mediump?.nsPerEval : row.gpu?.nsPerEval)?.median;
    if (!Number.isFinite(ns)) return {};
    costs[row.id] = ns;
  }
  return costs;
}

// The frame timing's parts (timeFrames.js), in the order the table lists them, with their names
// there; all but the hero after a change of n and the clear-coated peer are absent from results
// kept from before they were measured.
const FRAME_NAMES = [
  ['spheres', 'hero, a change of n'], ['spheresView', 'hero, a change of the view'], ['spheresOnePass', 'hero, one full-screen pass'],
  ['copy', 'a full-screen copy of the picture'], ['threePhysical', 'three.js MeshPhysicalMaterial, clear coat'],
  ['threePlain', 'three.js MeshPhysicalMaterial, no clear coat'],
];

/** The frame timing as kept in results: each part's cost and pixels, the ratios, the timer. */
function framesOf(frames) {
  const parts = FRAME_NAMES.filter(([key]) => frames[key])
    .map(([key]) => [key, { msPerFrame: frames[key].msPerFrame, pixels: frames[key].pixels }]);
  return {
    width: frames.width,
    height: frames.height,
    timer: frames.spheres.timer ?? null,
    ...Object.fromEntries(parts),
    ratio: frames.ratio,
    ...(Number.isFinite(frames.plainRatio) ? { plainRatio: frames.plainRatio } : {}),
  };
}

/**
 * The results object. gpu: timeMethodsGpu's result (or null), cpu: timeMethodsCpu's (or null),
 * frames: timeFrames' (or null), gpuErrors: the errors read back on the GPU (see methodErrors; or
 * null); meta: { date, userAgent, config, gpuError, gpuReadbackError, device (deviceInfo, for
 * when the GPU timing failed) }.
 * @param {BenchRun} [run]
 * @returns {BenchResults}
 */
export function benchResults({ gpu = null, cpu = null, frames = null, gpuErrors = null, meta = {} } = {}) {
  const methods = METHODS.map((m) => {
    const highp = gpu?.results?.highp?.[m.id];
    const mediump = gpu?.results?.mediump?.[m.id];
    return {
      id: m.id,
      label: m.label,
      kind: m.kind,
      staticCost: m.cost.static,
      gpu: highp || mediump ? {
        precision: 'highp', nsPerEval: highp?.nsPerEval ?? null, samples: highp?.samples ?? [],
        mediump: mediump ? { nsPerEval: mediump.nsPerEval, samples: mediump.samples } : null,
      } : null,
      cpu: cpu?.methods?.[m.id]
        ? { context: 'fp64', where: cpu.where ?? 'page', nsPerEval: cpu.methods[m.id].nsPerEval, samples: cpu.methods[m.id].samples }
        : null,
      error: methodErrors(m, gpuErrors),
    };
  });
  const results = {
    version: RESULTS_VERSION,
    date: meta.date ?? null,
    device: {
      renderer: (gpu?.device ?? meta.device)?.renderer ?? null,
      vendor: (gpu?.device ?? meta.device)?.vendor ?? null,
      webgl: (gpu?.device ?? meta.device)?.version ?? null,
      timer: gpu?.timer ?? null,
      gpuError: meta.gpuError ?? null,
      gpuReadbackError: meta.gpuReadbackError ?? null,
      userAgent: meta.userAgent ?? null,
    },
    config: {
      ...meta.config,
      gpu: gpu ? {
        size: gpu.size, loops: gpu.loops, passes: gpu.passes, bestOf: gpu.bestOf, repeats: gpu.repeats,
        evaluationsPerPass: gpu.evaluationsPerPass,
      } : null,
    },
    methods,
    frames: frames ? framesOf(frames) : null,
  };
  results.recommendations = Object.fromEntries(SCENES.map((scene) => {
    const costs = measuredCosts(results, scene);
    const costSource = Object.keys(costs).length ? t('costMeasuredGpu', { precision: gpuPrecisionFor(scene.precision) }) : t('costStatic');
    const pick = (budget) => {
      const r = recommendWithin(scene, costs, budget);
      return { methodId: r.methodId, invisible: r.invisible, budgetCodes: r.budgetCodes, reason: r.reason };
    };
    return [scene.id, { costSource, invisible: pick('invisible'), acceptable: pick('acceptable') }];
  }));
  return results;
}

const fixed = (v, digits) => (Number.isFinite(v) ? v.toFixed(digits) : v === Infinity ? 'inf' : '–');
const sci = (v) => (Number.isFinite(v) ? v.toExponential(2) : v === Infinity ? 'inf' : '–');

/** CSV columns (one row per method) for the panel's export and the toolbar. */
export function benchCsv(results) {
  const m = results.methods;
  const col = (f) => m.map((row) => f(row) ?? NaN);
  const columns = { method: m.map((row) => row.id), kind: m.map((row) => row.kind), static_cost: col((r) => r.staticCost) };
  for (const [name, get] of [
    ['gpu_highp', (r) => r.gpu?.nsPerEval], ['gpu_mediump', (r) => r.gpu?.mediump?.nsPerEval], ['cpu_fp64', (r) => r.cpu?.nsPerEval],
  ]) {
    for (const stat of ['median', 'min', 'max']) columns[`${name}_ns_${stat}`] = col((r) => get(r)?.[stat]);
  }
  const errorColumns = { ...Object.fromEntries(PRECISION_IDS.map((p) => [p, p])), gpuHighp: 'gpu_highp', gpuMediump: 'gpu_mediump' };
  for (const [p, name] of Object.entries(errorColumns)) {
    columns[`error_${name}_max`] = col((r) => r.error[p]?.max);
    columns[`error_${name}_mean`] = col((r) => r.error[p]?.mean);
    columns[`error_${name}_max_codes`] = col((r) => r.error[p]?.maxCodes);
  }
  return { filename: 'fresnel-lab-speed-accuracy.csv', columns };
}

/** The results as a fixed-width text table (stdout of npm run bench, bench/RESULTS.md). */
export function benchTable(results) {
  const ns = (s) => (s ? `${fixed(s.median, 3)} [${fixed(s.min, 3)}, ${fixed(s.max, 3)}]` : '–');
  const head = ['method', 'GPU highp ns/eval med [min, max]', 'GPU mediump ns/eval', 'CPU ns/eval', 'max|ΔR| fp64', 'fp32', 'fp16',
    'GPU highp', 'GPU mediump'];
  const rows = results.methods.map((r) => [
    r.id, ns(r.gpu?.nsPerEval), ns(r.gpu?.mediump?.nsPerEval), ns(r.cpu?.nsPerEval),
    sci(r.error.fp64.max), sci(r.error.fp32.max), sci(r.error.fp16.max), sci(r.error.gpuHighp?.max), sci(r.error.gpuMediump?.max),
  ]);
  const widths = head.map((h, i) => Math.max(h.length, ...rows.map((r) => r[i].length)));
  const line = (cells) => cells.map((c, i) => c.padEnd(widths[i])).join('  ').trimEnd();
  const out = [line(head), line(widths.map((w) => '-'.repeat(w))), ...rows.map(line)];
  const f = results.frames;
  if (f) {
    out.push('', `Frames at ${f.width}×${f.height} CSS px, ms${f.timer ? ` (${f.timer})` : ''}:`);
    for (const [key, name] of FRAME_NAMES) if (f[key]) out.push(`  ${name.padEnd(40)} ${ns(f[key].msPerFrame)}`);
    out.push(`  hero/peer ${fixed(f.ratio, 2)}${Number.isFinite(f.plainRatio) ? `, hero/plain peer ${fixed(f.plainRatio, 2)}` : ''}`);
  }
  out.push(`Device: ${results.device.renderer ?? 'no WebGL2'}; timer: ${results.device.timer ?? '–'}`
    + '; errors: JS emulation (fp64, fp32, fp16)'
    + `${results.methods.some((r) => r.error.gpuHighp) ? ' and read back from this GPU (highp, mediump)' : ''}`);
  return out.join('\n');
}
