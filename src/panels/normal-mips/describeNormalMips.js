// @ts-check
// The normal-mips panel in words and columns: the line of key numbers, the captions and the table's
// waiting line, the description under the panel and the CSV of the errors. Pure functions of the
// values and what the model and the scene hold, so they are tested in Node.
import { exponentFromAlpha } from '../../normals/lobeFormulas.js';
import { levelCount } from '../../normals/momentPyramid.js';
import { TECHNIQUE_NAMES, TECHNIQUES } from '../../normals/techniqueLayout.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { optionLabel } from '../panelText.js';
import { fixed } from '../../ui/format.js';
import { IOR } from './sceneSettings.js';

/** The maps as a sentence names them. */
const MAP_PHRASES = { bumps: 'bumps', grooves: 'V-grooves', checker: 'the slope checker', noise: 'value noise', mixed: 'the mixed map' };

/**
 * The line of key numbers under the picture.
 * @param {any} values
 * @param {{ built: { ms: number, where: string, size: number }, maxAnisotropy: number | null,
 *   floatLinear: boolean | null, problem: string }} facts  maxAnisotropy, floatLinear: null without a scene
 */
export function summaryText(values, { built, maxAnisotropy, floatLinear, problem }) {
  const size = Number(values.size);
  const levels = levelCount(size);
  const asked = Number(values.anisotropy);
  const aniso = maxAnisotropy === null ? 1 : Math.min(asked, maxAnisotropy);
  const anisoText = asked === 1 ? 'trilinear' : `${aniso}× anisotropic filtering`
    + (aniso < asked && maxAnisotropy !== null ? ` (this GPU offers at most ${maxAnisotropy}×)` : '');
  const level = values.level < 0 ? `automatic, ${anisoText}` : `forced to ${Math.min(values.level, levels - 1)}`;
  const chains = built.size ? `all six chains of the ${built.size}² map built in ${fixed(built.ms, 0)} ms (${built.where})`
    : `the six chains of the ${size}² map are being built`;
  return `${TECHNIQUE_NAMES[values.technique]}, ${optionLabel('normal-mips', 'precision', values.precision)}, ${values.channels} channels; `
    + `base Beckmann α = ${values.alpha} (Blinn-Phong s = ${fixed(exponentFromAlpha(values.alpha), 1)}); mip level ${level} `
    + `of 0–${levels - 1}; R0 = ${fixed(normalIncidence(1, IOR), 3)}; ${chains}.`
    + (values.precision === 'f32' && floatLinear === false ? ' This GPU cannot filter 32-bit float textures: pick 16-bit float.' : '')
    + (problem ? ` ${problem}` : '');
}

/** The overlay legend's top end. */
export const legendText = (/** @type {any} */ values) => `level ${levelCount(Number(values.size)) - 1} (difference: 0 to 0.25)`;

/**
 * The captions over the two halves of the picture and the error table's line while there are no errors.
 * @param {any} values
 * @param {{ samples: number, cap: number }} state  the scene's ground-truth progress
 */
export function statusText(values, { samples, cap }) {
  const name = TECHNIQUE_NAMES[values.technique];
  const truth = values.truth ? `ground truth, ${samples} samples/pixel` : 'ground truth off';
  const names = { split: [name, truth], technique: [name, ''], truth: ['', truth] };
  const [left, right] = Object.hasOwn(names, values.view) ? names[values.view] : [`|${name} − truth|`, truth];
  const pending = !values.truth ? 'Ground truth off: switch it on to compare techniques with numbers.'
    : samples < cap ? `Ground truth converging: ${samples} of ${cap} samples per pixel…`
      : 'Ground truth converged: measuring each technique against it…';
  return { left, right, pending };
}

/**
 * The description under the panel. errors: the scene's per-technique bandedRmse (or null);
 * shimmer: { technique: mean |Δ brightness| } or null; plotNote: the error-by-distance plot's note.
 */
export function describeText(/** @type {any} */ values, { errors, shimmer, plotNote }) {
  const level = values.level < 0 ? 'the automatic mip level' : `mip level ${values.level}`;
  const name = TECHNIQUE_NAMES[values.technique];
  const flicker = shimmer ? ` Shimmer of ${name}: ${fixed(shimmer[values.technique], 4)} mean brightness change per pixel.` : '';
  const head = `${name} on ${MAP_PHRASES[values.map]} at base α = ${values.alpha}, using ${level}`;
  if (!values.truth) return `${head}; the ground truth is off, so there is no error number.${flicker}`;
  // The sample count is live in the caption; the description changes when the errors arrive.
  if (!errors) return `${head}; the ground truth is still converging, so there is no error number yet.${flicker}`;
  const ranked = Object.entries(errors).sort((a, b) => a[1].rmse - b[1].rmse);
  const [best, worst] = [ranked[0], ranked.at(-1)];
  return `${head}: RMSE against the ground truth ${fixed(errors[values.technique].rmse, 4)}; `
    + `best ${TECHNIQUE_NAMES[best[0]]} (${fixed(best[1].rmse, 4)}), worst ${TECHNIQUE_NAMES[worst[0]]} (${fixed(worst[1].rmse, 4)}). `
    + `${plotNote}${flicker}`;
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
