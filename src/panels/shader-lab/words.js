// @ts-check
// What the shader lab says: the read-back GPU's words, what stopped the code, the line under it,
// the note on mediump, the words in place of the spheres and the maps, the maps' titles and names,
// the description and the CSV. Pure functions of the values and of what the runs hold (runs.js).
// Every sentence is the catalogue's ("shader-lab"); the driver's log and the student's code are
// kept as they were.
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';
import { refusalLine } from '../../gl/shaderError.js';
import { sci } from '../../ui/format.js';
import { criterion } from './exercises.js';
import { caseText } from './gradingCases.js';
import { PRECISIONS } from './runs.js';

/** @typedef {import('./runs.js').MapSide} MapSide */
/** @typedef {import('./runs.js').CodeError} CodeError */

/**
 * What the words read of the runs (createShaderLabRuns).
 * @typedef {object} ShaderLabState
 * @property {any} state  the last grade (runs.js Grade)
 * @property {string} problem  why nothing can be graded on this GPU, in the read-back GPU's words ('' when it can)
 * @property {boolean} lost  the context is lost
 * @property {boolean} fullMediump  mediump runs at full float32 precision here
 * @property {() => any} exercise  the current exercise
 * @property {() => any[]} cases  its grading cases
 */

const t = messages('shader-lab', english);

/** What the lab says about its GPU (createReadBackGpu's words), in the page's language when read. */
export const readBackWords = Object.freeze({
  get unavailable() { return t('unavailable'); },
  refused: (/** @type {string} */ line) => t('refused', { line }),
  get lost() { return t('lost'); },
});

/** An error in three significant digits, e+0 as before; NaN (and an infinite error) as NaN. */
const errorText = (x) => (Number.isFinite(x) ? sci(x, 2).replace(/e(?=\d)/, 'e+') : 'NaN');
const passed = (grade) => grade.results.filter((r) => r.pass).length;

/**
 * What stopped the code, by the student's line where there is one: the page's check, the driver's
 * log, or that the code was held back because the GPU stopped responding while it was graded.
 * @returns {CodeError[]}
 */
export function codeErrors(/** @type {ShaderLabState} */ { state }) {
  return state.stalled ? [{ line: null, message: t('stalled') }] : state.errors;
}

/** The exercise's criteria, each with its words and its result once graded (null before). */
export function criteriaRows(/** @type {ShaderLabState} */ lab) {
  return lab.exercise().criteria.map((id, i) => ({ ...criterion(id), result: lab.state.results[i] ?? null }));
}

/** The line under the code: the GPU's problem, the grade in short, or why there is none. */
export function summaryText(/** @type {ShaderLabState} */ lab) {
  const { state } = lab;
  if (lab.problem) return lab.problem;
  if (state.summary) {
    return t('summary', {
      passed: String(passed(state)), count: String(state.results.length), max: errorText(state.summary.max),
      where: state.summary.where, mean: errorText(state.summary.mean),
    });
  }
  return codeErrors(lab).length ? t('notGradedSeeAbove') : '';
}

/** Where mediump runs at full precision, the mediump criteria cannot fail here: said, when the exercise has one. */
export function noteText(/** @type {ShaderLabState} */ lab) {
  const hasMediump = lab.exercise().criteria.some((id) => criterion(id).precision === 'mediump');
  return hasMediump && lab.fullMediump ? t('mediumpCannotFail') : '';
}

/** In place of the spheres: the loss, why they are not drawn, or '' to show them. */
export function spheresMessage(/** @type {ShaderLabState} */ { lost, state }) {
  if (lost) return readBackWords.lost;
  const { spheres } = state;
  if (!spheres) return '';
  if (spheres === 'notGraded') return t('noSpheres');
  // It compiled alone but not beside the page's lighting code: say what the driver said.
  return t('spheresRefused', { said: refusalLine(spheres) || t('shaderDidNotCompile') });
}

export const spheresLabel = (/** @type {ShaderLabState} */ lab) => t(lab.exercise().kind === 'conductor' ? 'spheresGold' : 'spheresCoat');

export const mapTitle = (/** @type {{ precision: string }} */ values, /** @type {MapSide} */ side) => t(
  side === 'student' ? 'mapTitleStudent' : 'mapTitleReference',
  { precision: values.precision },
);

/** In place of a map: the loss, or that there is none until the code runs; '' with a map. */
export function mapMessage(/** @type {ShaderLabState} */ { lost, state }, /** @type {MapSide} */ side) {
  if (state.maps[side]) return '';
  return lost ? readBackWords.lost : t('noMap');
}

/** A map's accessible name, or that there is none. */
export function mapLabel(/** @type {ShaderLabState} */ { state }, /** @type {MapSide} */ side) {
  const map = state.maps[side];
  if (!map) return t('noMapLabel');
  const cells = map.width * map.height;
  const args = { failing: String(cells - map.counts.fine), cells: String(cells) };
  return t(side === 'student' ? 'mapLabelStudent' : 'mapLabelReference', args);
}

/** The description: the exercise and its grade, what stopped the code, or the GPU's problem. */
export function describeText(/** @type {ShaderLabState} */ lab) {
  const { state } = lab;
  const { title } = lab.exercise();
  if (lab.problem) return t('describeProblem', { exercise: title, problem: lab.problem });
  const errors = codeErrors(lab);
  if (errors.length) {
    const said = errors.map((e) => (e.line ? t('errorAtLine', { line: String(e.line), message: e.message }) : e.message));
    return t('describeRefused', { exercise: title, errors: said.join(' ') });
  }
  if (!state.summary) return t('describeNotYet', { exercise: title });
  const failing = state.results.filter((r) => !r.pass).map((r) => r.label);
  const args = {
    exercise: title, passed: String(passed(state)), count: String(state.results.length), failing: failing.join('; '),
    max: errorText(state.summary.max), where: state.summary.where, mean: errorText(state.summary.mean),
  };
  return t(failing.length ? 'describeGradedFailing' : 'describeGraded', args);
}

/** The grading cases with the exact values and the student's, per precision (per channel for a conductor). */
export function gradeCsv(/** @type {ShaderLabState} */ lab) {
  const ex = lab.exercise();
  const cases = lab.cases();
  const { values } = lab.state;
  /** @type {Record<string, Array<number | string>>} */
  const columns = { case: cases.map(caseText), cos: cases.map((c) => c.cos) };
  const yours = (p, i) => (values[p] ? values[p][i] : '');
  if (ex.kind === 'conductor') {
    ['red', 'green', 'blue'].forEach((name, ch) => {
      columns[`exact_${name}`] = cases.map((c) => c.exact[ch]);
      for (const p of PRECISIONS) columns[`yours_${p}_${name}`] = cases.map((_, i) => yours(p, i * 3 + ch));
    });
  } else {
    columns.nI = cases.map((c) => c.nI);
    columns.nT = cases.map((c) => c.nT);
    columns.exact = cases.map((c) => c.exact);
    for (const p of PRECISIONS) columns[`yours_${p}`] = cases.map((_, i) => yours(p, i));
  }
  return { filename: `shader-lab-${ex.id}.csv`, columns };
}
