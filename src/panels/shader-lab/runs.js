// @ts-check
// The shader lab's state apart from its DOM: the exercise and the code, the grading run (the
// student's function compiled into a read-back shader, evaluated over the grading grid in highp and
// mediump and, for a dielectric, over the stability map's grid; graded against the float64 core),
// the spheres painted with it, and every sentence the lab says. The GPU is a read-back GPU
// (createReadBackGpu.js) whose prepared part is the sphere painter; in Node a stand-in. The code is
// only ever compiled by the GPU driver, never run as JavaScript (studentShader.js refuses loops,
// directives and line continuations first). Every sentence is the catalogue's ("shader-lab").
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';
import { refusalLine, ShaderError } from '../../gl/shaderError.js';
import { classifyGrid, gridInputs } from '../../methods/classifyGrid.js';
import { classify } from '../../methods/stabilityMap.js';
import { sci } from '../../ui/format.js';
import { isStaleRun } from '../shared/createRunGate.js';
import { caseInputs, caseText, conductorCases, dielectricCases } from './gradingCases.js';
import { criterion, exerciseById, exerciseMetal } from './exercises.js';
import { errorSummary, gradeExercise } from './gradeExercise.js';
import { checkStudentCode, readCompileLog, studentFragment } from './studentShader.js';

/** @typedef {import('../shared/createReadBackGpu.js').ReadBackGpu} ReadBackGpu */
/** @typedef {'student' | 'reference'} MapSide */
/** @typedef {{ line: number | null, message: string }} CodeError */

export const PRECISIONS = Object.freeze(['highp', 'mediump']);
const MAP_GRID = { width: 91, height: 54 }; // θ every 1°, n_i/n_t from 0.4 to 2.5

const t = messages('shader-lab', english);

/** What the lab says about its GPU (createReadBackGpu's words), in the page's language when read. */
export const readBackWords = Object.freeze({
  get unavailable() { return t('unavailable'); },
  refused: (/** @type {string} */ line) => t('refused', { line }),
  get lost() { return t('lost'); },
});

/** An error in three significant digits, e+0 as before; NaN (and an infinite error) as NaN. */
const errorText = (x) => (Number.isFinite(x) ? sci(x, 2).replace(/e(?=\d)/, 'e+') : 'NaN');

/**
 * values: the panel's values, read at each call ({ exercise, code, precision }); gpu: the lab's
 * read-back GPU, which the runs own from here (dispose frees it); onRead: after each grading that
 * reached the GPU (the panel's frameDrawn).
 * @param {{ values: { exercise: string, code: string, precision: string }, gpu: ReadBackGpu, onRead?: () => void }} options
 */
export function createShaderLabRuns({ values, gpu, onRead = () => {} }) {
  const grading = gpu.gate(); // one grading at a time: a newer one, a loss or dispose makes it stale
  const exercise = () => exerciseById(values.exercise);
  const code = () => values.code || exercise().start;
  const casesCache = new Map();
  const casesOf = (ex) => {
    if (!casesCache.has(ex.id)) casesCache.set(ex.id, ex.kind === 'conductor' ? conductorCases(exerciseMetal(ex)) : dielectricCases());
    return casesCache.get(ex.id);
  };
  const mapGrid = classify('exact-cg', 'fp64', MAP_GRID); // the grid (and the float64 map, all fine)
  const mapInputs = { inputs: gridInputs(mapGrid) };
  const referenceMaps = new Map(); // 'exercise|precision' → map: the reference answer does not change
  let studentSource = '';
  // Code whose grading was under way when the context went: it may be what stopped the GPU, so it
  // is not graded again by itself (the Grade button still does).
  let stalled = null;

  /**
   * @typedef {object} Grade
   * @property {any[]} results  one per criterion of the exercise (gradeExercise)
   * @property {any} summary  errorSummary in highp, or null
   * @property {CodeError[]} errors  what refused the code (the page's check or the driver), by the student's line
   * @property {Record<string, Float32Array>} values  the read-back per precision
   * @property {{ student: any, reference: any }} maps  the stability maps (dielectric exercises)
   * @property {string} spheres  why there are no spheres, or ''
   */
  /** @type {Grade} */
  let state = { results: [], summary: null, errors: [], values: {}, maps: { student: null, reference: null }, spheres: '' };

  /** The exercise's function in `text` over `inputs` in one precision; throws ShaderError. */
  function evaluate(evaluator, ex, text, role, precision, { inputs, extra = null }) {
    return evaluator.evaluateSource({
      key: `${role}|${ex.kind}|${precision}|${text}`, // the source itself: no two codes share a program
      source: studentFragment(text, { kind: ex.kind, precision }),
      inputs,
      extra,
      channels: ex.kind === 'conductor' ? 3 : 1,
    });
  }

  /**
   * Grades the current code. A run of the grading gate: a newer grading begun meanwhile, a loss
   * found during it or dispose makes it stale, and what it read is dropped (after a loss the code
   * is taken for what stalled the GPU).
   */
  function grade() {
    const ex = exercise();
    const text = code();
    const refused = checkStudentCode(text);
    /** @type {Grade} */
    const next = {
      results: [], summary: null, errors: refused, values: {}, maps: { student: null, reference: null }, spheres: t('noSpheres'),
    };
    state = next;
    if (refused.length || !gpu.ready) return;
    if (stalled === text) {
      next.errors = [{ line: null, message: t('stalled') }];
      return;
    }
    const run = grading.begin();
    if (text !== studentSource) gpu.evaluator?.forget('student|'); // only the newest code's programs are kept
    studentSource = text;
    const cases = casesOf(ex);
    const read = (role, source, precision, inputs) => gpu.read(run,
      (evaluator) => evaluate(evaluator, ex, source, role, precision, inputs));
    try {
      const inputs = caseInputs(cases);
      for (const precision of PRECISIONS) next.values[precision] = read('student', text, precision, inputs);
      if (ex.kind === 'dielectric') {
        const at = values.precision;
        const refKey = `${ex.id}|${at}`;
        if (!referenceMaps.has(refKey)) {
          const answer = read('reference', ex.reference, at, mapInputs);
          referenceMaps.set(refKey, classifyGrid(answer, mapGrid, { methodId: 'reference', precision: at }));
        }
        next.maps = {
          student: classifyGrid(read('student', text, at, mapInputs), mapGrid, { methodId: 'student', precision: at }),
          reference: referenceMaps.get(refKey),
        };
      }
    } catch (error) {
      if (isStaleRun(error)) {
        if (gpu.lost) stalled = text;
        if (state === next) state = { ...next, values: {}, maps: { student: null, reference: null } }; // nothing of it is shown
        return;
      }
      if (error instanceof ShaderError) {
        next.errors = readCompileLog(error.log, ex.signature);
        if (!next.errors.length) next.errors = [{ line: null, message: error.message }];
        return;
      }
      throw error;
    } finally {
      onRead();
    }
    next.results = gradeExercise(ex, cases, (p) => next.values[p]);
    next.summary = errorSummary(cases, next.values.highp);
    next.spheres = '';
  }

  const fullMediump = () => Boolean(gpu.ready && gpu.precision?.probe.mediumpIsFullPrecision);
  const passed = () => state.results.filter((r) => r.pass).length;

  return {
    get state() { return state; },
    exercise,
    code,
    grade,
    /** The student asked for a grade: code that stalled the GPU before is graded once more. */
    retry() { stalled = null; },
    /** The exercise's criteria, each with its result once graded (null before). */
    criteriaRows() {
      return exercise().criteria.map((id, i) => ({ ...criterion(id), result: state.results[i] ?? null }));
    },
    /** The line under the code: the GPU's problem, the grade in short, or why there is none. */
    summary() {
      if (gpu.problem) return gpu.problem;
      if (state.summary) {
        return t('summary', {
          passed: String(passed()), count: String(state.results.length), max: errorText(state.summary.max),
          where: state.summary.where, mean: errorText(state.summary.mean),
        });
      }
      return state.errors.length ? t('notGradedSeeAbove') : '';
    },
    /** Where mediump runs at full precision, the mediump criteria cannot fail here: said, when the exercise has one. */
    note() {
      const hasMediump = exercise().criteria.some((id) => criterion(id).precision === 'mediump');
      return hasMediump && fullMediump() ? t('mediumpCannotFail') : '';
    },
    /** In place of the spheres: the loss, why they could not be drawn, or '' to show them. */
    spheresMessage: () => (gpu.lost ? readBackWords.lost : state.spheres),
    spheresLabel: () => t(exercise().kind === 'conductor' ? 'spheresGold' : 'spheresCoat'),
    mapTitle: (/** @type {MapSide} */ side) => t(side === 'student' ? 'mapTitleStudent' : 'mapTitleReference', {
      precision: values.precision,
    }),
    /** In place of a map: the loss, or that there is none until the code runs; '' with a map. */
    mapMessage: (/** @type {MapSide} */ side) => (state.maps[side] ? '' : gpu.lost ? readBackWords.lost : t('noMap')),
    mapLabel(/** @type {MapSide} */ side) {
      const map = state.maps[side];
      if (!map) return t('noMapLabel');
      const cells = map.width * map.height;
      const args = { failing: String(cells - map.counts.fine), cells: String(cells) };
      return t(side === 'student' ? 'mapLabelStudent' : 'mapLabelReference', args);
    },
    /**
     * Paints both spheres into `target` (a 2D canvas) with the graded code; returns what to say in
     * their place when the code does not compile beside the page's lighting code, else ''.
     * @param {HTMLCanvasElement} target
     */
    paint(target) {
      const painter = /** @type {any} */ (gpu.prepared);
      if (!painter || !gpu.ready || state.spheres || !state.summary) return '';
      const ex = exercise();
      try {
        painter.paint(target, code(), ex, exerciseMetal(ex));
      } catch (error) {
        if (!(error instanceof ShaderError)) throw error;
        // It compiled alone but not beside the page's lighting code: say what the driver said.
        state.spheres = t('spheresRefused', { said: refusalLine(error) || t('shaderDidNotCompile') });
      }
      return state.spheres;
    },
    describe() {
      const { title } = exercise();
      if (gpu.problem) return t('describeProblem', { exercise: title, problem: gpu.problem });
      if (state.errors.length) {
        const errors = state.errors.map((e) => (e.line ? t('errorAtLine', { line: String(e.line), message: e.message }) : e.message));
        return t('describeRefused', { exercise: title, errors: errors.join(' ') });
      }
      if (!state.summary) return t('describeNotYet', { exercise: title });
      const failing = state.results.filter((r) => !r.pass).map((r) => r.label);
      const args = {
        exercise: title, passed: String(passed()), count: String(state.results.length), failing: failing.join('; '),
        max: errorText(state.summary.max), where: state.summary.where, mean: errorText(state.summary.mean),
      };
      return t(failing.length ? 'describeGradedFailing' : 'describeGraded', args);
    },
    csv() {
      const ex = exercise();
      const cases = casesOf(ex);
      /** @type {Record<string, Array<number | string>>} */
      const columns = { case: cases.map(caseText), cos: cases.map((c) => c.cos) };
      const yours = (p, i) => (state.values[p] ? state.values[p][i] : '');
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
    },
    /** Frees the GPU: the grading runs, the painter, the evaluator and the context. */
    dispose() { gpu.dispose(); },
  };
}
