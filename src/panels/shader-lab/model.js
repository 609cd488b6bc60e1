// @ts-check
// The shader lab's state apart from its DOM: the exercise and the code, the grading run (the
// student's function compiled into a read-back shader, evaluated over the grading grid in highp and
// mediump and, for a dielectric, over the stability map's grid; graded against the float64 core),
// the spheres painted with it, and every sentence the lab says. The GPU is a read-back GPU
// (createReadBackGpu.js) whose prepared part is the sphere painter; in Node a stand-in. The code is
// only ever compiled by the GPU driver, never run as JavaScript (studentShader.js refuses loops,
// directives and line continuations first).
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
const NO_SPHERES = 'No spheres until the code compiles and runs.';
const NO_MAP = 'No map until the code compiles and runs.';
const STALLED = 'The graphics card stopped responding while this code was graded, and the browser reset it. '
  + 'Change the code, or press Grade to try it once more.';

/** What the lab says about its GPU (createReadBackGpu's words). */
export const readBackWords = Object.freeze({
  unavailable: 'Grading needs WebGL2 with float render targets.',
  refused: (/** @type {string} */ line) => `This GPU could not compile the lab’s own shaders, so nothing can be graded here: ${line}.`,
  lost: 'The graphics context was lost; grading resumes when it is back.',
});

/** An error in three significant digits, e+0 as before; NaN (and an infinite error) as NaN. */
const errorText = (x) => (Number.isFinite(x) ? sci(x, 2).replace(/e(?=\d)/, 'e+') : 'NaN');

/**
 * values: the panel's values, read at each call ({ exercise, code, precision }); gpu: the lab's
 * read-back GPU, which the model owns from here (dispose frees it); onRead: after each grading that
 * reached the GPU (the panel's frameDrawn).
 * @param {{ values: { exercise: string, code: string, precision: string }, gpu: ReadBackGpu, onRead?: () => void }} options
 */
export function createShaderLabModel({ values, gpu, onRead = () => {} }) {
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
    const next = { results: [], summary: null, errors: refused, values: {}, maps: { student: null, reference: null }, spheres: NO_SPHERES };
    state = next;
    if (refused.length || !gpu.ready) return;
    if (stalled === text) {
      next.errors = [{ line: null, message: STALLED }];
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
        return `${passed()} of ${state.results.length} criteria pass. Against the exact R (highp): largest error `
          + `${errorText(state.summary.max)} at ${state.summary.where}; mean ${errorText(state.summary.mean)}.`;
      }
      return state.errors.length ? 'Not graded: see what stopped it above.' : '';
    },
    /** Where mediump runs at full precision, the mediump criteria cannot fail here: said, when the exercise has one. */
    note() {
      const hasMediump = exercise().criteria.some((id) => criterion(id).precision === 'mediump');
      return hasMediump && fullMediump()
        ? 'This GPU runs mediump at full float32 precision, so the mediump criteria cannot fail here; '
          + 'on a phone with half precision they can.'
        : '';
    },
    /** In place of the spheres: the loss, why they could not be drawn, or '' to show them. */
    spheresMessage: () => (gpu.lost ? readBackWords.lost : state.spheres),
    spheresLabel: () => (exercise().kind === 'conductor'
      ? 'Two gold spheres reflecting the sky: the first with your function, the second with the exact conductor Fresnel.'
      : 'Two red spheres under a clear coat of n = 1.5: the first with your function, the second with the exact Fresnel reflectance.'),
    mapTitle: (/** @type {MapSide} */ side) => `${side === 'student' ? 'Your function' : 'A reference answer'} · ${values.precision}`,
    /** In place of a map: the loss, or that there is none until the code runs; '' with a map. */
    mapMessage: (/** @type {MapSide} */ side) => (state.maps[side] ? '' : gpu.lost ? readBackWords.lost : NO_MAP),
    mapLabel(/** @type {MapSide} */ side) {
      const map = state.maps[side];
      if (!map) return 'No map';
      return `Stability map of ${side === 'student' ? 'your function' : 'a reference answer'}: `
        + `${map.width * map.height - map.counts.fine} of ${map.width * map.height} cells fail`;
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
        const said = refusalLine(error) || 'the shader did not compile';
        state.spheres = `The spheres could not be drawn beside the page’s lighting code: ${said} `
          + '(is one of your names environment, skyLight, castStage or linearToSrgb?).';
      }
      return state.spheres;
    },
    describe() {
      const ex = exercise();
      if (gpu.problem) return `${ex.title}: ${gpu.problem}`;
      if (state.errors.length) {
        return `${ex.title}: not graded; ${state.errors.map((e) => (e.line ? `line ${e.line}: ${e.message}` : e.message)).join(' ')}`;
      }
      if (!state.summary) return `${ex.title}: not graded yet.`;
      const failing = state.results.filter((r) => !r.pass).map((r) => r.label);
      const failures = failing.length ? ` (failing: ${failing.join('; ')})` : '';
      return `${ex.title}: ${passed()} of ${state.results.length} criteria pass${failures}. `
        + `Largest error against the exact R in highp ${errorText(state.summary.max)} at ${state.summary.where}; `
        + `mean ${errorText(state.summary.mean)}.`;
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
