// @ts-check
// The stability panel's state apart from its DOM: which two maps a precision shows, the JavaScript
// map (stabilityMap.classify), the GPU map read back once per method and precision (the values do
// not depend on the tolerance, so only the classes are redone when it moves), the probed cell, and
// every sentence the panel says. The GPU is a read-back GPU (createReadBackGpu.js); in Node a
// stand-in. Whether mediump really is half precision here is measured by rendering 1 + 2^-f, not
// taken from the driver, whose answer Safari/iOS has got wrong (webglfundamentals "WebGL Precision
// Issues"). Every sentence is the catalogue's ("stability"), numbers through src/ui/format.js.
import english from 'virtual:messages/en/stability';
import { messages } from '../../i18n/messages.js';
import { cellAt, classifyGrid, criticalAngleDeg, gridInputs } from '../../methods/classifyGrid.js';
import { methodById } from '../../methods/methods.js';
import { contextFor } from '../../methods/rounding.js';
import { classify, classifyValue, CLASS_NAMES } from '../../methods/stabilityMap.js';
import { angle, fixed, precise as significant } from '../../ui/format.js';
import { CLASS_LABELS } from '../shared/createMapFigure.js';
import { emulationGapWords } from '../shared/emulationGapWords.js';
import { isStaleRun } from '../shared/createRunGate.js';

/** @typedef {import('../shared/createReadBackGpu.js').ReadBackGpu} ReadBackGpu */
/** @typedef {'gpu' | 'js'} Side */
/** @typedef {{ i: number, j: number }} Cell */

const t = messages('stability', english);

/** What the panel says about its GPU (createReadBackGpu's words), in the page's language when read. */
export const readBackWords = Object.freeze({
  get unavailable() { return t('unavailable'); },
  refused: (/** @type {string} */ line) => t('refused', { line }),
  get lost() { return t('lost'); },
  restartFailed: (/** @type {Error} */ error) => t('restartFailed', { error: error.message }),
});

/** The two maps a precision shows: the GPU qualifier, the JS context, and which one was chosen. */
export function pairFor(precision) {
  const half = precision === 'fp16' || precision === 'mediump';
  return {
    gpu: half ? 'mediump' : 'highp',
    js: precision === 'fp64' ? 'fp64' : half ? 'fp16' : 'fp32',
    selected: precision === 'highp' || precision === 'mediump' ? 'gpu' : 'js',
  };
}

// Six significant digits: a value beside the exact R, NaN and ±Infinity as JavaScript names them.
const precise = (v) => (Number.isFinite(v) ? significant(v, 6) : String(v));
const failing = (map) => map.width * map.height - map.counts.fine;

/**
 * values: the panel's values, read at each update ({ method, precision, tolerance }); gpu: the
 * panel's read-back GPU, which the model owns from here (dispose frees it); onRead: after each
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
  let gpuProblem = gpu.problem; // why there is no GPU map, when there is none
  if (gpu.evaluator) onRead(); // the precision probe was read back

  /** The GPU map of the current method and qualifier over `grid`, read back once; null, and why, when there is none. */
  function gpuMap(grid) {
    if (!gpu.evaluator) {
      gpuProblem = gpu.problem;
      return null;
    }
    const key = `${values.method}|${pair.gpu}`;
    if (!gpuValues.has(key)) {
      if (!gpu.ready) { // lost: the maps already read back still stand
        gpuProblem = gpu.problem;
        return null;
      }
      try {
        const inputs = gridInputs(grid);
        const read = (evaluator) => evaluator.evaluate({ methodId: values.method, precision: pair.gpu, inputs });
        gpuValues.set(key, gpu.read(reading.begin(), read));
      } catch (error) { // the JavaScript map still stands
        gpuProblem = isStaleRun(error) ? gpu.problem : t('evaluationFailed', { error: error.message });
        return null;
      }
      onRead();
    }
    return { ...classifyGrid(gpuValues.get(key), grid, { methodId: values.method, precision: pair.gpu }), values: gpuValues.get(key) };
  }

  const probe = () => gpu.precision?.probe ?? null;
  const fullMediump = () => Boolean(probe()?.mediumpIsFullPrecision && pair.gpu === 'mediump');
  const sideTitle = (/** @type {Side} */ side) => (side === 'gpu'
    ? t('titleGpu', { precision: pair.gpu })
    : t('titleJs', { precision: contextFor(pair.js).name }));

  return {
    get maps() { return maps; },
    get pair() { return pair; },
    get probeCell() { return probeCell; },
    /** What mediump and highp are on this GPU (probePrecision), or null. */
    get precisionProbe() { return probe(); },
    /** The values changed: both maps for the current method, precision and tolerance. */
    update() {
      pair = pairFor(values.precision);
      const js = classify(values.method, pair.js, { tolerance: values.tolerance });
      maps = { js, gpu: gpuMap(js) };
    },
    /** The note above the maps: what mediump is here, or why there is no GPU map. */
    note() {
      if (!maps.gpu) return gpuProblem;
      const { probe: measured, claimed } = /** @type {import('../shared/createReadBackGpu.js').PrecisionFacts} */ (gpu.precision);
      const args = {
        bits: String(measured.mediumpBits), claimed: claimed?.mediump ? String(claimed.mediump.precision + 1) : '', ...emulationGapWords(),
      };
      if (measured.mediumpIsFullPrecision) return t(args.claimed ? 'mediumpFullClaimed' : 'mediumpFull', args);
      return t(args.claimed ? 'mediumpReducedClaimed' : 'mediumpReduced', args);
    },
    /** The message in place of the GPU map ('' when there is one). */
    gpuMessage: () => (maps.gpu ? '' : gpuProblem),
    fullMediump,
    sideTitle,
    /** A map's accessible name, or null when the side has no map. */
    mapLabel(/** @type {Side} */ side) {
      const map = maps[side];
      if (!map) return null;
      const method = methodById(values.method).label;
      return t('mapLabel', { method, side: sideTitle(side), failing: String(failing(map)), cells: String(map.width * map.height) });
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
    /** The probed cell in words: θ, n_i/n_t, θc, the exact R and each map's value and class ('' without a probe). */
    readout() {
      if (!probeCell || !maps.js) return '';
      const cell = cellAt(maps.js, probeCell.i, probeCell.j);
      const method = methodById(values.method);
      const critical = criticalAngleDeg(cell.ratio);
      const where = { theta: angle(cell.thetaDeg, 2), ratio: fixed(cell.ratio, 3) };
      const parts = [
        critical === null ? t('readoutCell', where) : t('readoutCellCritical', { ...where, critical: angle(critical, 2) }),
        t('readoutExact', { value: precise(cell.reference) }),
      ];
      const k = cell.j * maps.js.width + cell.i;
      if (maps.gpu) {
        const value = precise(maps.gpu.values[k]);
        parts.push(t('readoutGpu', { precision: pair.gpu, value, class: CLASS_LABELS[CLASS_NAMES[maps.gpu.cells[k]]] }));
      }
      const jsValue = method.evaluate(pair.js, cell.cos, cell.ratio, 1);
      const jsClass = CLASS_NAMES[classifyValue(jsValue, cell.reference, values.tolerance)];
      parts.push(t('readoutJs', { precision: contextFor(pair.js).label, value: precise(jsValue), class: CLASS_LABELS[jsClass] }));
      return parts.join(' · ');
    },
    describe() {
      const words = (map) => t('counts', {
        fine: String(map.counts.fine), above: String(map.counts.aboveTolerance), tolerance: significant(values.tolerance, 3),
        outside: String(map.counts.outOfRange), notFinite: String(map.counts.notFinite),
      });
      const args = {
        method: methodById(values.method).label, width: String(maps.js.width), height: String(maps.js.height),
        js: contextFor(pair.js).label, jsCounts: words(maps.js),
      };
      const text = maps.gpu ? t('describe', { ...args, gpu: pair.gpu, gpuCounts: words(maps.gpu) }) : t('describeNoGpu', args);
      return fullMediump() ? `${text} ${t('describeFullMediump')}` : text;
    },
    csv() {
      /** @type {Record<string, Array<number | string>>} */
      const columns = { class: [...CLASS_NAMES] };
      if (maps.gpu) columns[`gpu_${pair.gpu}`] = CLASS_NAMES.map((c) => maps.gpu.counts[c]);
      columns[`js_${pair.js}`] = CLASS_NAMES.map((c) => maps.js.counts[c]);
      return { filename: `stability-${values.method}-${values.precision}.csv`, columns };
    },
    /** The caption of the exported picture. */
    pngCaption: () => (fullMediump() ? t('pngCaptionFull', { method: methodById(values.method).label }) : methodById(values.method).label),
    /** Frees the GPU (its runs, evaluator and context) and the values read back. */
    dispose() {
      gpu.dispose();
      gpuValues.clear();
      maps = { gpu: null, js: null };
    },
  };
}
