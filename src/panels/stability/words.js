// @ts-check
// What the stability panel says: the note on what mediump is here, why there is no GPU map, the
// maps' titles and accessible names, the probe's readout, the description, the CSV of the counts and
// the exported picture's caption. Pure functions of the values and of what the runs hold (runs.js),
// so each is tested in Node with maps made by hand. Every sentence is the catalogue's ("stability"),
// numbers through src/ui/format.js.
import english from 'virtual:messages/en/stability';
import { messages } from '../../i18n/messages.js';
import { methodById } from '../../methods/methods.js';
import { contextFor } from '../../methods/rounding.js';
import { CLASS_NAMES } from '../../methods/stabilityMap.js';
import { angle, fixed, precise as significant } from '../../ui/format.js';
import { CLASS_LABELS } from '../shared/classLabels.js';
import { emulationGapWords } from '../shared/emulationGapWords.js';

/** @typedef {import('./runs.js').Side} Side */

/**
 * What the words read of the runs (createStabilityRuns, or a snapshot of them in a test).
 * @typedef {object} StabilityState
 * @property {{ gpu: any, js: any }} maps  classify()'s maps (gpu: null when there is none)
 * @property {{ gpu: string, js: string }} pair  the GPU qualifier and the JS context shown
 * @property {import('./runs.js').MissingGpuMap | null} missing  why there is no GPU map
 * @property {import('./runs.js').PrecisionFacts | null} precision  what mediump is here, measured and claimed
 * @property {boolean} fullMediump  the GPU map is of mediump, which runs at full precision here
 * @property {import('./runs.js').Probed | null} [probed]  the probed cell's numbers
 */

const t = messages('stability', english);

/** What the panel says about its GPU (createReadBackGpu's words), in the page's language when read. */
export const readBackWords = Object.freeze({
  get unavailable() { return t('unavailable'); },
  refused: (/** @type {string} */ line) => t('refused', { line }),
  get lost() { return t('lost'); },
  restartFailed: (/** @type {Error} */ error) => t('restartFailed', { error: error.message }),
});

// Six significant digits: a value beside the exact R, NaN and ±Infinity as JavaScript names them.
const precise = (v) => (Number.isFinite(v) ? significant(v, 6) : String(v));
const failing = (map) => map.width * map.height - map.counts.fine;

/** The message in place of the GPU map: why there is none ('' when there is one). */
export function gpuMessage(/** @type {StabilityState} */ { maps, missing }) {
  if (maps.gpu || !missing) return '';
  return 'error' in missing ? t('evaluationFailed', { error: missing.error.message }) : missing.problem;
}

/** The note above the maps: what mediump is here, or why there is no GPU map. */
export function noteText(/** @type {StabilityState} */ state) {
  if (!state.maps.gpu || !state.precision) return gpuMessage(state);
  const { probe: measured, claimed } = state.precision;
  const args = {
    bits: String(measured.mediumpBits), claimed: claimed?.mediump ? String(claimed.mediump.precision + 1) : '', ...emulationGapWords(),
  };
  if (measured.mediumpIsFullPrecision) return t(args.claimed ? 'mediumpFullClaimed' : 'mediumpFull', args);
  return t(args.claimed ? 'mediumpReducedClaimed' : 'mediumpReduced', args);
}

/** A map's title: where it was computed, and in which precision. */
export const sideTitle = (/** @type {{ gpu: string, js: string }} */ pair, /** @type {Side} */ side) => (side === 'gpu'
  ? t('titleGpu', { precision: pair.gpu })
  : t('titleJs', { precision: contextFor(pair.js).name }));

/** A map's accessible name, or null when the side has no map. */
export function mapLabel(/** @type {{ method: string }} */ values, /** @type {StabilityState} */ state, /** @type {Side} */ side) {
  const map = state.maps[side];
  if (!map) return null;
  return t('mapLabel', {
    method: methodById(values.method).label, side: sideTitle(state.pair, side),
    failing: String(failing(map)), cells: String(map.width * map.height),
  });
}

/** The probed cell in words: θ, n_i/n_t, θc, the exact R and each map's value and class ('' without a probe). */
export function readoutText(/** @type {StabilityState} */ { probed, pair }) {
  if (!probed) return '';
  const where = { theta: angle(probed.thetaDeg, 2), ratio: fixed(probed.ratio, 3) };
  const parts = [
    probed.critical === null ? t('readoutCell', where) : t('readoutCellCritical', { ...where, critical: angle(probed.critical, 2) }),
    t('readoutExact', { value: precise(probed.reference) }),
  ];
  if (probed.gpu) {
    parts.push(t('readoutGpu', { precision: pair.gpu, value: precise(probed.gpu.value), class: CLASS_LABELS[probed.gpu.class] }));
  }
  const { js } = probed;
  parts.push(t('readoutJs', { precision: contextFor(pair.js).label, value: precise(js.value), class: CLASS_LABELS[js.class] }));
  return parts.join(' · ');
}

/**
 * The description: each map's counts per class; without a GPU map, why there is none, in the same
 * words as the message in its place (the read-back GPU's for its problem, or the evaluation's error).
 * @param {{ method: string, tolerance: number }} values
 * @param {StabilityState} state
 */
export function describeText(values, state) {
  const { maps, pair } = state;
  const words = (map) => t('counts', {
    fine: String(map.counts.fine), above: String(map.counts.aboveTolerance), tolerance: significant(values.tolerance, 3),
    outside: String(map.counts.outOfRange), notFinite: String(map.counts.notFinite),
  });
  const args = {
    method: methodById(values.method).label, width: String(maps.js.width), height: String(maps.js.height),
    js: contextFor(pair.js).label, jsCounts: words(maps.js),
  };
  const text = maps.gpu
    ? t('describe', { ...args, gpu: pair.gpu, gpuCounts: words(maps.gpu) })
    : t('describeNoGpu', { ...args, problem: gpuMessage(state) });
  return state.fullMediump ? `${text} ${t('describeFullMediump')}` : text;
}

/** The counts per class of each map, as CSV columns. */
export function mapsCsv(/** @type {{ method: string, precision: string }} */ values, /** @type {StabilityState} */ { maps, pair }) {
  /** @type {Record<string, Array<number | string>>} */
  const columns = { class: [...CLASS_NAMES] };
  if (maps.gpu) columns[`gpu_${pair.gpu}`] = CLASS_NAMES.map((c) => maps.gpu.counts[c]);
  columns[`js_${pair.js}`] = CLASS_NAMES.map((c) => maps.js.counts[c]);
  return { filename: `stability-${values.method}-${values.precision}.csv`, columns };
}

/** The caption of the exported picture: the method, and where mediump runs at full precision, that. */
export function pngCaption(/** @type {{ method: string }} */ values, /** @type {StabilityState} */ state) {
  const method = methodById(values.method).label;
  return state.fullMediump ? t('pngCaptionFull', { method }) : method;
}
