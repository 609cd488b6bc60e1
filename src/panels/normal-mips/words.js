// @ts-check
// The normal-mips panel in words and columns: the line of key numbers, the captions and the table's
// waiting line, the line over the stage while chains build, why a shimmer measurement stopped, the
// description under the panel and the CSV of the errors. Pure functions of the values and what the
// runs (runs.js) and the scene hold, so they are tested in Node.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { exponentFromAlpha } from '../../normals/lobeFormulas.js';
import { levelCount } from '../../normals/momentPyramid.js';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { optionLabel } from '../controlText.js';
import { fixed, tickLabel } from '../../ui/format.js';
import { schema } from './schema.js';
import { IOR } from './sceneSettings.js';
import { techniqueName } from './techniqueName.js';

const t = messages('normal-mips', english);

/** Base α as its control writes it: the decimals of its step, in the page's language. */
const alphaText = (/** @type {number} */ alpha) => tickLabel(alpha, schema.alpha.step);

/**
 * The line over the stage for the runs' chain build (runs.js ChainBuildState): building a map of
 * its size, or why the build failed; '' once the chains are there.
 * @param {import('./runs.js').ChainBuildState} state
 */
export function busyText(state) {
  if (!state) return '';
  if ('error' in state) return t('buildFailed', { reason: state.error.message });
  return t('building', { size: String(state.size) });
}

/** Why the last shimmer measurement ended without numbers (runs.js ShimmerStop); '' when it did not. */
export const shimmerStoppedText = (/** @type {import('./runs.js').ShimmerStop} */ stopped) => (stopped === 'lost' ? t('shimmer.lost') : '');

/** Where the chains were built, in words: on the page's thread (0 workers) or in so many workers. */
export const builtWhere = (/** @type {number} */ workers) => t('builtWhere', { workers });

/**
 * Why the chains are built on the page's thread, in words, from the builder's problem
 * (createChainBuilder: null, or { reason, detail }); '' when they are not.
 * @param {{ reason: string, detail?: string } | null} problem
 */
export function chainProblemText(problem) {
  if (!problem) return '';
  return t(`chains.${problem.reason}`, { reason: problem.detail ?? '' });
}

/**
 * The line of key numbers under the picture.
 * @param {any} values
 * @param {{ built: { ms: number, workers: number, size: number }, maxAnisotropy: number | null,
 *   floatLinear: boolean | null, problem: string }} facts  maxAnisotropy, floatLinear: null without a scene;
 *   problem: chainProblemText's sentence ('' for none)
 */
export function summaryText(values, { built, maxAnisotropy, floatLinear, problem }) {
  const size = Number(values.size);
  const levels = levelCount(size);
  const asked = Number(values.anisotropy);
  const taps = maxAnisotropy === null ? 1 : Math.min(asked, maxAnisotropy);
  const filtering = asked === 1 ? 'trilinear' : taps < asked && maxAnisotropy !== null ? 'capped' : 'anisotropic';
  return t('summary', {
    technique: techniqueName(values.technique),
    precision: optionLabel('normal-mips', 'precision', values.precision),
    channels: Number(values.channels),
    alpha: alphaText(values.alpha),
    exponent: fixed(exponentFromAlpha(values.alpha), 1),
    level: values.level < 0 ? 'auto' : String(Math.min(values.level, levels - 1)),
    filtering,
    taps: String(taps),
    most: String(maxAnisotropy),
    top: String(levels - 1),
    r0: fixed(normalIncidence(1, IOR), 3),
    built: built.size ? 'yes' : 'no',
    size: String(built.size || size),
    ms: fixed(built.ms, 0),
    where: builtWhere(built.workers),
  })
    + (values.precision === 'f32' && floatLinear === false ? ` ${t('noFloatFilter')}` : '')
    + (problem ? ` ${problem}` : '');
}

/** The overlay legend's top end. */
export const legendText = (/** @type {any} */ values) => t('legendTop', {
  level: String(levelCount(Number(values.size)) - 1), scale: fixed(0.25, 2),
});

/**
 * The captions over the two halves of the picture and the error table's line while there are no errors.
 * @param {any} values
 * @param {{ samples: number, cap: number }} state  the scene's ground-truth progress
 */
export function statusText(values, { samples, cap }) {
  const name = techniqueName(values.technique);
  const truth = values.truth ? t('caption.truth', { samples: String(samples) }) : t('caption.truthOff');
  const names = { split: [name, truth], technique: [name, ''], truth: ['', truth] };
  const [left, right] = Object.hasOwn(names, values.view) ? names[values.view] : [t('caption.difference', { technique: name }), truth];
  const pending = !values.truth ? t('pending.truthOff')
    : samples < cap ? t('pending.converging', { samples: String(samples), cap: String(cap) })
      : t('pending.measuring');
  return { left, right, pending };
}

/**
 * The description under the panel. errors: the scene's per-technique bandedRmse (or null);
 * shimmer: { technique: mean |Δ brightness| } or null; plotNote: the error-by-distance plot's note.
 */
export function describeText(/** @type {any} */ values, { errors, shimmer, plotNote }) {
  const name = techniqueName(values.technique);
  const flicker = shimmer ? ` ${t('describeShimmer', { technique: name, value: fixed(shimmer[values.technique], 4) })}` : '';
  const head = {
    technique: name,
    map: t(`mapPhrase.${values.map}`),
    alpha: alphaText(values.alpha),
    level: values.level < 0 ? 'auto' : String(values.level),
  };
  // The sample count is live in the caption; the description changes when the errors arrive.
  if (!values.truth || !errors) return `${t('describe', { ...head, state: values.truth ? 'converging' : 'off' })}${flicker}`;
  const ranked = Object.entries(errors).sort((a, b) => a[1].rmse - b[1].rmse);
  const [best, worst] = [ranked[0], ranked.at(-1)];
  return `${t('describe', {
    ...head,
    state: 'errors',
    rmse: fixed(errors[values.technique].rmse, 4),
    best: techniqueName(best[0]),
    bestRmse: fixed(best[1].rmse, 4),
    worst: techniqueName(worst[0]),
    worstRmse: fixed(worst[1].rmse, 4),
  })} ${plotNote}${flicker}`;
}

/** The errors as CSV columns: one row per technique, the overall RMSE and one column per mip-level band. */
export function errorsCsv(/** @type {any} */ values, /** @type {any} */ errors) {
  if (!errors) return { filename: 'normal-mips-errors.csv', columns: { technique: [] } };
  /** @type {Record<string, Array<number | string>>} */
  const columns = { technique: [...TECHNIQUES], rmse: TECHNIQUES.map((t) => errors[t].rmse) };
  errors[TECHNIQUES[0]].bands.forEach((/** @type {{ level: number }} */ b) => {
    columns[`rmse_level_${b.level}`] = TECHNIQUES.map((t) => errors[t].bands[b.level].rmse);
  });
  return { filename: `normal-mips-${values.map}-errors.csv`, columns };
}
