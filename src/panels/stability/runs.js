// @ts-check
// The stability panel's state apart from its DOM: which two maps a precision shows, the JavaScript
// map (stabilityMap.classify), the GPU map read back once per method and precision (the values do
// not depend on the tolerance, so only the classes are redone when it moves), why there is no GPU
// map when there is none, and the probed cell with its numbers. The GPU is a read-back GPU
// (createReadBackGpu.js); in Node a stand-in. Whether mediump really is half precision here is
// measured by rendering 1 + 2^-f, not taken from the driver, whose answer Safari/iOS has got wrong
// (webglfundamentals "WebGL Precision Issues"). What the panel says of all this is words.js's.
import { cellAt, classifyGrid, criticalAngleDeg, gridInputs } from '../../methods/classifyGrid.js';
import { methodById } from '../../methods/methods.js';
import { classify, classifyValue, CLASS_NAMES } from '../../methods/stabilityMap.js';
import { isStaleRun } from '../shared/createRunGate.js';

/** @typedef {import('../shared/createReadBackGpu.js').ReadBackGpu} ReadBackGpu */
/** @typedef {import('../shared/createReadBackGpu.js').PrecisionFacts} PrecisionFacts */
/** @typedef {'gpu' | 'js'} Side */
/** @typedef {{ i: number, j: number }} Cell */

/**
 * Why there is no GPU map: the read-back GPU's own problem, in the words it was given (no WebGL2 or
 * no float targets, a refused shader, a lost context, a failed restore), or the error of an
 * evaluation that failed on a working GPU.
 * @typedef {{ problem: string } | { error: Error }} MissingGpuMap
 */

/**
 * The probed cell in numbers: where it is (θ, n_i/n_t, the critical angle or null), the exact R,
 * and each map's value there with its class (gpu: null without a GPU map).
 * @typedef {{ thetaDeg: number, ratio: number, critical: number | null, reference: number,
 *   gpu: { value: number, class: string } | null, js: { value: number, class: string } }} Probed
 */

/** The two maps a precision shows: the GPU qualifier, the JS context, and which one was chosen. */
export function pairFor(precision) {
  const half = precision === 'fp16' || precision === 'mediump';
  return {
    gpu: half ? 'mediump' : 'highp',
    js: precision === 'fp64' ? 'fp64' : half ? 'fp16' : 'fp32',
    selected: precision === 'highp' || precision === 'mediump' ? 'gpu' : 'js',
  };
}

/**
 * values: the panel's values, read at each update ({ method, precision, tolerance }); gpu: the
 * panel's read-back GPU, which the runs own from here (dispose frees it); onRead: after each
 * read-back (the panel's frameDrawn).
 * @param {{ values: { method: string, precision: string, tolerance: number }, gpu: ReadBackGpu, onRead?: () => void }} options
 */
export function createStabilityRuns({ values, gpu, onRead = () => {} }) {
  const reading = gpu.gate(); // one GPU map at a time: a loss or dispose makes it stale
  const gpuValues = new Map(); // 'method|qualifier' → Float32Array (independent of the tolerance)
  /** @type {{ gpu: any, js: any }} */
  let maps = { gpu: null, js: null };
  let pair = pairFor(values.precision);
  /** @type {Cell | null} */
  let probeCell = null;
  /** @type {MissingGpuMap | null} */
  let missing = gpu.evaluator ? null : { problem: gpu.problem };
  if (gpu.evaluator) onRead(); // the precision probe was read back

  /** The GPU map of the current method and qualifier over `grid`, read back once; null, and why, when there is none. */
  function gpuMap(grid) {
    missing = null;
    if (!gpu.evaluator) {
      missing = { problem: gpu.problem };
      return null;
    }
    const key = `${values.method}|${pair.gpu}`;
    if (!gpuValues.has(key)) {
      if (!gpu.ready) { // lost: the maps already read back still stand
        missing = { problem: gpu.problem };
        return null;
      }
      try {
        const inputs = gridInputs(grid);
        const read = (evaluator) => evaluator.evaluate({ methodId: values.method, precision: pair.gpu, inputs });
        gpuValues.set(key, gpu.read(reading.begin(), read));
      } catch (error) { // the JavaScript map still stands
        missing = isStaleRun(error) ? { problem: gpu.problem } : { error };
        return null;
      }
      onRead();
    }
    return { ...classifyGrid(gpuValues.get(key), grid, { methodId: values.method, precision: pair.gpu }), values: gpuValues.get(key) };
  }

  const probe = () => gpu.precision?.probe ?? null;

  return {
    /** The GPU and the JavaScript map of the current values (gpu: null when there is none). */
    get maps() { return maps; },
    get pair() { return pair; },
    get probeCell() { return probeCell; },
    /** What mediump and highp are on this GPU (probePrecision), or null. */
    get precisionProbe() { return probe(); },
    /** What mediump and highp are here, measured and claimed by the driver, or null before the evaluator ever started. */
    get precision() { return gpu.precision; },
    /** Why there is no GPU map (null while there is one). */
    get missing() { return maps.gpu ? null : missing; },
    /** The GPU map is of mediump, and mediump runs at full precision here. */
    get fullMediump() { return Boolean(probe()?.mediumpIsFullPrecision && pair.gpu === 'mediump'); },
    /** The values changed: both maps for the current method, precision and tolerance. */
    update() {
      pair = pairFor(values.precision);
      const js = classify(values.method, pair.js, { tolerance: values.tolerance });
      maps = { js, gpu: gpuMap(js) };
    },
    setProbe(/** @type {Cell | null} */ cell) { probeCell = cell; },
    /**
     * A key on a map moves the probe (arrows, Shift for 10 cells, Home and End to the row's ends);
     * true when the key was one of them. From no probe, the move starts at the middle.
     */
    moveProbe(/** @type {string} */ key, shift = false) {
      const map = maps.js;
      const step = shift ? 10 : 1;
      const moves = {
        ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowDown: [0, -step], ArrowUp: [0, step], Home: [-map.width, 0], End: [map.width, 0],
      };
      if (!Object.hasOwn(moves, key)) return false;
      const cell = probeCell ?? { i: Math.floor(map.width / 2), j: Math.floor(map.height / 2) };
      const [di, dj] = moves[key];
      probeCell = { i: Math.min(map.width - 1, Math.max(0, cell.i + di)), j: Math.min(map.height - 1, Math.max(0, cell.j + dj)) };
      return true;
    },
    /**
     * The probed cell's numbers (null without a probe): the GPU's value read back there, and the
     * JavaScript emulation's, evaluated for this one cell at the current precision.
     * @returns {Probed | null}
     */
    get probed() {
      if (!probeCell || !maps.js) return null;
      const cell = cellAt(maps.js, probeCell.i, probeCell.j);
      const k = cell.j * maps.js.width + cell.i;
      const jsValue = methodById(values.method).evaluate(pair.js, cell.cos, cell.ratio, 1);
      return {
        thetaDeg: cell.thetaDeg,
        ratio: cell.ratio,
        critical: criticalAngleDeg(cell.ratio),
        reference: cell.reference,
        gpu: maps.gpu ? { value: maps.gpu.values[k], class: CLASS_NAMES[maps.gpu.cells[k]] } : null,
        js: { value: jsValue, class: CLASS_NAMES[classifyValue(jsValue, cell.reference, values.tolerance)] },
      };
    },
    /** Frees the GPU (its runs, evaluator and context) and the values read back. */
    dispose() {
      gpu.dispose();
      gpuValues.clear();
      maps = { gpu: null, js: null };
    },
  };
}

/** @typedef {ReturnType<typeof createStabilityRuns>} StabilityRuns */
