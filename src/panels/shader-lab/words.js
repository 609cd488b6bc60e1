// @ts-check
// What the shader lab says: the read-back GPU's words, what stopped the code, the criteria with
// their reasons, the line under the code, the note on mediump, the words in place of the spheres
// and the maps, the maps' titles and names, the description and the CSV. Pure functions of the
// values and of what the runs hold (runs.js keeps codes and numbers). Every sentence is the
// catalogue's ("shader-lab"), every number written by src/ui/format.js; the driver's log and the
// student's code are kept as they were.
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';
import { refusalLine, shaderErrorMessage } from '../../gl/shaderError.js';
import { angle, fixed, precise, rounded, sci, tickLabel } from '../../ui/format.js';
import { optionLabel } from '../controlText.js';
import { criterion } from './exercises.js';
import { PRECISIONS } from './runs.js';

/** @typedef {import('./runs.js').MapSide} MapSide */
/** @typedef {import('./runs.js').Grade} Grade */
/** @typedef {import('./studentShader.js').CodeProblem} CodeProblem */
/** @typedef {import('./exercises.js').Exercise} Exercise */
/** @typedef {import('./gradingCases.js').GradingCase} GradingCase */
/** @typedef {import('./gradeExercise.js').CriterionResult} CriterionResult */
/** @typedef {import('./gradeExercise.js').Channel} Channel */
/** @typedef {{ line: number | null, message: string }} CodeError  what stopped the code, in words, at the student's line */

/**
 * What the words read of the runs (createShaderLabRuns).
 * @typedef {object} ShaderLabState
 * @property {Grade} state  the last grade
 * @property {string} problem  why nothing can be graded on this GPU, in the read-back GPU's words ('' when it can)
 * @property {boolean} lost  the context is lost
 * @property {boolean} fullMediump  mediump runs at full float32 precision here
 * @property {() => Exercise} exercise  the current exercise
 * @property {() => GradingCase[]} cases  its grading cases
 */

const t = messages('shader-lab', english);

/** What the lab says about its GPU (createReadBackGpu's words), in the page's language when read. */
export const readBackWords = Object.freeze({
  get unavailable() { return t('unavailable'); },
  refused: (/** @type {string} */ line) => t('refused', { line }),
  get lost() { return t('lost'); },
});

/** An error in three significant digits, e+0 as before; NaN (and an infinite error) as NaN. */
const errorText = (/** @type {number} */ x) => (Number.isFinite(x) ? sci(x, 2).replace(/e(?=\d)/, 'e+') : 'NaN');
const passed = (/** @type {Grade} */ grade) => grade.results.filter((r) => r.pass).length;

/** An exercise's title: the exercise control's option. */
export const exerciseTitle = (/** @type {Exercise} */ exercise) => optionLabel('shader-lab', 'exercise', exercise.id);

/** What a criterion asks, by its id. */
export const criterionLabel = (/** @type {string} */ id) => t(`criterion.${id}`);

/**
 * A float32 input as the shortest decimal that gives it back (1 + 2⁻²³ is 1.0000001, fround(1.33)
 * is 1.33), tiny ones in e-notation (−1e−7): the decimals it needs, found as toFixed rounds.
 * @param {number} x
 */
function float32Text(x) {
  let decimals = 0;
  while (decimals < 9 && Math.fround(rounded(x, decimals)) !== x) decimals += 1;
  if (x === 0 || Math.abs(x) >= 1e-3) return fixed(x, decimals);
  return sci(x, Math.max(0, decimals + Math.floor(Math.log10(Math.abs(x)))));
}

/**
 * A case as a reason or the CSV names it: "θ = 41.81°, n_i 1.5 → n_t 1" or "cos θ = 1.0000001, …",
 * θ to 5 decimals near the critical angle and at grazing, where the steps are that small.
 * @param {GradingCase} c
 */
export function caseText(c) {
  const where = c.thetaDeg === null
    ? `cos θ = ${float32Text(c.cos)}`
    : `θ = ${angle(c.thetaDeg, c.tag === 'critical' || c.tag === 'grazing' ? 5 : 2)}`;
  return 'n' in c ? where : `${where}, n_i ${float32Text(c.nI)} → n_t ${float32Text(c.nT)}`;
}

/**
 * Where a value is: its case, with its colour channel if it has one.
 * @param {{ case: GradingCase, channel: Channel | null }} at
 */
export const whereText = (at) => (at.channel ? t('whereChannel', { case: caseText(at.case), channel: at.channel }) : caseText(at.case));

/** A value in a reason: four decimals, a tiny one in two digits (1.2e−5), NaN and ±Infinity by name. */
const valueText = (/** @type {number} */ x) => {
  if (!Number.isFinite(x)) return Number.isNaN(x) ? 'NaN' : precise(x);
  return x === 0 ? '0' : Math.abs(x) >= 1e-3 ? fixed(x, 4) : sci(x, 1);
};
/** A tolerance as written in the criterion (0.00001, 0.001), with the page's decimal separator. */
const toleranceText = (/** @type {number} */ v) => tickLabel(v, 1e-9);

/**
 * Why a criterion passed or failed, naming its worst case (or its largest difference).
 * @param {CriterionResult} result
 */
export function reasonText(result) {
  const { code, worst } = result;
  if (code === 'noCase' || !worst) return t('noCase');
  const args = {
    where: whereText(worst), target: result.target, checked: String(result.checked), failed: String(result.failed),
    tolerance: result.tolerance === null ? '' : toleranceText(result.tolerance), value: valueText(worst.value),
  };
  if (code === 'allWithin') return t('allWithin', { ...args, difference: valueText(worst.error) });
  if (code === 'aboveTolerance') {
    return t('aboveTolerance', { ...args, reference: valueText(worst.reference), error: valueText(worst.error) });
  }
  return t(code, args); // allSane, notFinite, outOfRange
}

/** The catalogue's key for each refusal of the page's own. */
const REFUSAL = {
  noCode: 'noCode', loop: 'refusedLoop', continuation: 'refusedContinuation', directive: 'refusedDirective', precision: 'refusedPrecision',
};

/**
 * What stopped the code, in words: the page's refusal, or the driver's words as it wrote them
 * (with the page's around them where they name the page's wrapper).
 * @param {CodeProblem} problem
 * @param {Exercise} exercise  the exercise graded (its signature, for a missing function)
 */
export function problemText(problem, exercise) {
  switch (problem.code) {
    case 'tooLong': return t('tooLong', { length: String(problem.length), max: String(problem.max) });
    case 'driver': return problem.text;
    case 'afterLastLine': return t('afterLastLine', { message: problem.text });
    case 'missingFunction': return t('defineFunction', { signature: exercise.signature, message: problem.text });
    case 'refused': return shaderErrorMessage(problem.error);
    default: return t(REFUSAL[problem.code]);
  }
}

/**
 * What stopped the code, by the student's line where there is one: the page's check, the driver's
 * log, or that the code was held back because the GPU stopped responding while it was graded.
 * @returns {CodeError[]}
 */
export function codeErrors(/** @type {ShaderLabState} */ lab) {
  const { state } = lab;
  if (state.stalled) return [{ line: null, message: t('stalled') }];
  return state.errors.map((problem) => ({ line: problem.line, message: problemText(problem, lab.exercise()) }));
}

/** The exercise's criteria, each with its words and, once graded, its result and the reason (null and '' before). */
export function criteriaRows(/** @type {ShaderLabState} */ lab) {
  return lab.exercise().criteria.map((id, i) => {
    const result = lab.state.results[i] ?? null;
    return { id, label: criterionLabel(id), precision: criterion(id).precision, result, reason: result ? reasonText(result) : '' };
  });
}

/** Where the largest error is ('' without a case). */
const summaryWhere = (/** @type {import('./gradeExercise.js').ErrorSummary} */ summary) => (summary.worst ? whereText(summary.worst) : '');

/** The line under the code: the GPU's problem, the grade in short, or why there is none. */
export function summaryText(/** @type {ShaderLabState} */ lab) {
  const { state } = lab;
  if (lab.problem) return lab.problem;
  if (state.summary) {
    return t('summary', {
      passed: String(passed(state)), count: String(state.results.length), max: errorText(state.summary.max),
      where: summaryWhere(state.summary), mean: errorText(state.summary.mean),
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
  const title = exerciseTitle(lab.exercise());
  if (lab.problem) return t('describeProblem', { exercise: title, problem: lab.problem });
  const errors = codeErrors(lab);
  if (errors.length) {
    const said = errors.map((e) => (e.line ? t('errorAtLine', { line: String(e.line), message: e.message }) : e.message));
    return t('describeRefused', { exercise: title, errors: said.join(' ') });
  }
  if (!state.summary) return t('describeNotYet', { exercise: title });
  const failing = state.results.filter((r) => !r.pass).map((r) => criterionLabel(r.id));
  const args = {
    exercise: title, passed: String(passed(state)), count: String(state.results.length), failing: failing.join('; '),
    max: errorText(state.summary.max), where: summaryWhere(state.summary), mean: errorText(state.summary.mean),
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
    const metal = /** @type {import('./gradingCases.js').ConductorCase[]} */ (cases);
    ['red', 'green', 'blue'].forEach((name, ch) => {
      columns[`exact_${name}`] = metal.map((c) => c.exact[ch]);
      for (const p of PRECISIONS) columns[`yours_${p}_${name}`] = cases.map((_, i) => yours(p, i * 3 + ch));
    });
  } else {
    const dielectric = /** @type {import('./gradingCases.js').DielectricCase[]} */ (cases);
    columns.nI = dielectric.map((c) => c.nI);
    columns.nT = dielectric.map((c) => c.nT);
    columns.exact = dielectric.map((c) => c.exact);
    for (const p of PRECISIONS) columns[`yours_${p}`] = cases.map((_, i) => yours(p, i));
  }
  return { filename: `shader-lab-${ex.id}.csv`, columns };
}
