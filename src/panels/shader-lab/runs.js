// @ts-check
// The shader lab's state apart from its DOM: the exercise and the code, the grading run (the
// student's function compiled into a read-back shader, evaluated over the grading grid in highp and
// mediump and, for a dielectric, over the stability map's grid; graded against the float64 core)
// and the spheres painted with it. The GPU is a read-back GPU (createReadBackGpu.js) whose prepared
// part is the sphere painter; in Node a stand-in. The code is only ever compiled by the GPU driver,
// never run as JavaScript (studentShader.js refuses loops, directives and line continuations
// first). What the lab says of its grade is words.js's: these runs, and the helpers they import,
// keep codes and numbers (a problem's code and line, a criterion's result and its worst case).
import { ShaderError } from '../../gl/shaderError.js';
import { classifyGrid, gridInputs } from '../../methods/classifyGrid.js';
import { classify } from '../../methods/stabilityMap.js';
import { isStaleRun } from '../shared/createRunGate.js';
import { caseInputs, conductorCases, dielectricCases } from './gradingCases.js';
import { exerciseById, exerciseMetal } from './exercises.js';
import { errorSummary, gradeExercise } from './gradeExercise.js';
import { checkStudentCode, readCompileLog, studentFragment } from './studentShader.js';

/** @typedef {import('../shared/createReadBackGpu.js').ReadBackGpu} ReadBackGpu */
/** @typedef {import('../../methods/classifyGrid.js').GridMap} GridMap */
/** @typedef {import('./gradingCases.js').GradingCase} GradingCase */
/** @typedef {import('./exercises.js').Exercise} Exercise */
/** @typedef {'student' | 'reference'} MapSide */

/**
 * Why there are no spheres: the code was not graded (it did not compile or run, or the GPU could
 * not grade it), or it compiled alone but the driver refused it beside the page's lighting code
 * (the error); null when they can be drawn.
 * @typedef {'notGraded' | ShaderError | null} SpheresStop
 */

/**
 * The last grade.
 * @typedef {object} Grade
 * @property {import('./gradeExercise.js').CriterionResult[]} results  one per criterion of the exercise (gradeExercise)
 * @property {import('./gradeExercise.js').ErrorSummary | null} summary  the error against the exact R in highp (errorSummary)
 * @property {import('./studentShader.js').CodeProblem[]} errors  what refused the code (the page's check or the driver), as codes
 *   at the student's lines
 * @property {boolean} stalled  the code was held back: the GPU stopped responding while it was graded before
 * @property {Partial<Record<Precision, Float32Array>>} values  the read-back per precision
 * @property {Record<MapSide, GridMap | null>} maps  the stability maps (dielectric exercises)
 * @property {SpheresStop} spheres  why there are no spheres (null: they can be drawn)
 */

/** @typedef {'highp' | 'mediump'} Precision */
/** @type {ReadonlyArray<Precision>} */
export const PRECISIONS = Object.freeze(['highp', 'mediump']);
const MAP_GRID = { width: 91, height: 54 }; // θ every 1°, n_i/n_t from 0.4 to 2.5

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
  /** @type {Map<string, GradingCase[]>} */
  const casesCache = new Map();
  const casesOf = (/** @type {Exercise} */ ex) => {
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

  /** @type {Grade} */
  let state = {
    results: [], summary: null, errors: [], stalled: false, values: {}, maps: { student: null, reference: null }, spheres: null,
  };

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
      results: [], summary: null, errors: refused, stalled: false, values: {},
      maps: { student: null, reference: null }, spheres: /** @type {SpheresStop} */ ('notGraded'),
    };
    state = next;
    if (refused.length || !gpu.ready) return;
    if (stalled === text) {
      next.stalled = true;
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
        next.errors = readCompileLog(error.log);
        if (!next.errors.length) next.errors = [{ line: null, code: 'refused', error }];
        return;
      }
      throw error;
    } finally {
      onRead();
    }
    next.results = gradeExercise(ex, cases, (p) => next.values[p]);
    next.summary = errorSummary(cases, next.values.highp);
    next.spheres = null;
  }

  return {
    /** The last grade (Grade). */
    get state() { return state; },
    /** Why nothing can be graded on this GPU now, in the read-back GPU's words ('' when it can). */
    get problem() { return gpu.problem; },
    /** The context is lost (until it is restored). */
    get lost() { return gpu.lost; },
    /** mediump runs at full float32 precision on this GPU, so a mediump criterion cannot fail here. */
    get fullMediump() { return Boolean(gpu.ready && gpu.precision?.probe.mediumpIsFullPrecision); },
    exercise,
    code,
    /** The grading cases of the current exercise (gradingCases.js), made once per exercise. */
    cases: () => casesOf(exercise()),
    /** The values changed: grades the current code. */
    update: grade,
    /** The student asked for a grade: code that stalled the GPU before is graded once more. */
    retry() { stalled = null; },
    /**
     * Paints both spheres into `target` (a 2D canvas) with the graded code; returns why they are
     * not there when the code does not compile beside the page's lighting code (the driver's
     * error, kept in state.spheres too), else null.
     * @param {HTMLCanvasElement} target
     * @returns {SpheresStop}
     */
    paint(target) {
      const painter = /** @type {any} */ (gpu.prepared);
      if (!painter || !gpu.ready || state.spheres || !state.summary) return null;
      const ex = exercise();
      try {
        painter.paint(target, code(), ex, exerciseMetal(ex));
      } catch (error) {
        if (!(error instanceof ShaderError)) throw error;
        state.spheres = error; // it compiled alone but not beside the page's lighting code
      }
      return state.spheres;
    },
    /** Frees the GPU: the grading runs, the painter, the evaluator and the context. */
    dispose() { gpu.dispose(); },
  };
}
