// CPU cost of every Fresnel method as the JS in methods.js runs it (float64 context): ns per
// evaluation, with the spread over repeats. Each repeat times every method once, in turn, so a
// slow drift of the machine (another tab, a turbo clock) spreads over all methods alike. Inputs
// vary per evaluation (a golden-ratio sequence over the scene domains of scenes.js) so the JIT
// cannot fold them, and every result feeds a sink that is returned, so none can be dropped.
// Pure apart from the clock (injectable) and setTimeout (to yield to the page between methods).
import { METHODS } from './methods.js';
import { sceneById } from './scenes.js';

const GOLDEN = 0.6180339887498949;

/** { median, min, max } of finite samples (median of an even count: mean of the middle two). */
export function spreadOf(samples) {
  const sorted = samples.filter(Number.isFinite).sort((a, b) => a - b);
  if (sorted.length === 0) return { median: NaN, min: NaN, max: NaN };
  const mid = sorted.length >> 1;
  const median = sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
  return { median, min: sorted[0], max: sorted[sorted.length - 1] };
}

/**
 * count argument lists per kind: dielectric [cos, nI, nT] over the plastic scene's index pairs,
 * conductor [cos, n, k, f0] over the metal scene's cases; cos runs over (0, 1) by the golden ratio.
 */
export function cpuInputs(kind, count = 2048) {
  const cases = sceneById(kind === 'conductor' ? 'metal' : 'plastic').cases;
  return Array.from({ length: count }, (_, i) => [((i + 0.5) * GOLDEN) % 1, ...cases[i % cases.length]]);
}

const pause = () => new Promise((resolve) => { setTimeout(resolve, 0); });

function runLoops(method, inputs, loops) {
  let sink = 0;
  for (let l = 0; l < loops; l += 1) {
    for (let i = 0; i < inputs.length; i += 1) {
      const a = inputs[i];
      sink += method.evaluate('fp64', a[0], a[1], a[2], a[3]); // a[3] is F0 (conductors) or unused
    }
  }
  return sink;
}

/**
 * Times methods (default: all of methods.js). Options: repeats (per method), minMs (the least
 * time one timed block runs; its loop count is calibrated per method, after a warm-up),
 * count (inputs per block), now (a ms clock), onProgress(done, total), signal (an AbortSignal:
 * aborting rejects with its reason). Resolves to { methods: { [id]: { nsPerEval: { median, min,
 * max }, samples (ns per eval, one per repeat), evaluations (per block) } }, sink } where sink
 * is the sum of every result, kept so the work is observable.
 */
export async function timeMethodsCpu({
  methods = METHODS, repeats = 5, minMs = 20, count = 2048, now = () => performance.now(), onProgress, signal,
} = {}) {
  const inputs = { dielectric: cpuInputs('dielectric', count), conductor: cpuInputs('conductor', count) };
  const loops = new Map();
  const samples = new Map(methods.map((m) => [m.id, []]));
  const total = methods.length * (repeats + 1);
  let done = 0;
  let sink = 0;
  const step = async () => {
    done += 1;
    onProgress?.(done, total);
    await pause();
    signal?.throwIfAborted();
  };
  signal?.throwIfAborted();
  // Calibration: grow the loop count until one block takes minMs, twice: the first pass also
  // warms the JIT up, so the second finds the count for optimized code.
  const calibrate = (method, start) => {
    let n = start;
    for (;;) {
      const t0 = now();
      sink += runLoops(method, inputs[method.kind], n);
      const elapsed = now() - t0;
      if (elapsed >= minMs || n >= 1 << 20) return n;
      n = elapsed > 0 ? Math.max(n * 2, Math.ceil((n * minMs * 1.1) / elapsed)) : n * 4;
    }
  };
  for (const method of methods) {
    loops.set(method.id, calibrate(method, calibrate(method, 1)));
    await step();
  }
  for (let r = 0; r < repeats; r += 1) {
    for (const method of methods) {
      const n = loops.get(method.id);
      const t0 = now();
      sink += runLoops(method, inputs[method.kind], n);
      const elapsed = now() - t0;
      samples.get(method.id).push((elapsed * 1e6) / (n * count));
      await step();
    }
  }
  return {
    methods: Object.fromEntries(methods.map((m) => [m.id, {
      nsPerEval: spreadOf(samples.get(m.id)), samples: samples.get(m.id), evaluations: loops.get(m.id) * count,
    }])),
    sink,
  };
}
