// @ts-check
// Panel `shader-lab`: the student writes the Fresnel function in GLSL; the page compiles it into a
// read-back shader on this GPU, evaluates it over the grading grid in highp and in mediump, reads
// the results back from a float target and grades them against the float64 core, criterion by
// criterion, with the worst case named; beside it, the stability map of the student's function and
// of the reference answer. The code is only ever compiled by the GPU driver, never run as
// JavaScript (studentShader.js refuses loops and directives first).
import { WebGL2Unavailable } from '../../gl/contextBudget.js';
import { createContext } from '../../gl/createContext.js';
import { disposeMethodsGpu, GpuFloatUnavailable, methodsGpu, ShaderCompileFailed } from '../../gl/evaluateMethodsGpu.js';
import { classifyGrid, gridInputs } from '../../optics/classifyGrid.js';
import { classify } from '../../optics/stabilityMap.js';
import { hashSeed } from '../../homework/seededRandom.js';
import { drawMap } from '../shared/drawMap.js';
import { composePng } from '../shared/composePng.js';
import { buildShaderLabDom } from './buildShaderLabDom.js';
import { createCodeEditor } from './createCodeEditor.js';
import { caseInputs, caseText, conductorCases, dielectricCases } from './gradingCases.js';
import { criterion, exerciseById, exerciseMetal } from './exercises.js';
import { errorSummary, gradeExercise } from './gradeExercise.js';
import { checkStudentCode, readCompileLog, studentFragment } from './studentShader.js';
import { createSpherePainter } from './paintSpheres.js';
import { ShaderError } from '../../gl/createProgram.js';
import './styles.css';
import { schema } from './schema.js';

export { schema };

const STORE = 'fresnel-lab:shader-lab:';
const PRECISIONS = ['highp', 'mediump'];
const MAP_GRID = { width: 91, height: 54 }; // θ every 1°, n_i/n_t from 0.4 to 2.5
const sci = (x) => (Number.isFinite(x) ? x.toExponential(2).replace('-', '−') : 'NaN');

function stored(exerciseId) {
  try {
    return window.localStorage.getItem(STORE + exerciseId);
  } catch {
    return null; // storage refused: the link still keeps the code
  }
}
function store(exerciseId, code) {
  try {
    if (code) window.localStorage.setItem(STORE + exerciseId, code);
    else window.localStorage.removeItem(STORE + exerciseId);
  } catch { /* refused */ }
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildShaderLabDom(root);
  ctx.bind(ctx.gui.addFolder('Exercise'), ['exercise', 'precision', 'homework']);
  // A link or a message without code: the code this browser kept for the exercise, if any.
  if (!values.code && stored(values.exercise)) ctx.set({ code: stored(values.exercise) });

  const canvas = document.createElement('canvas');
  let context = null;
  let gpu = null;
  let painter = null;
  let gpuProblem = '';
  let lost = false;
  const startGpu = () => {
    try {
      context = createContext(canvas);
      gpu = methodsGpu(context.gl);
      painter = createSpherePainter(context.gl);
      gpuProblem = '';
    } catch (error) {
      if (!(error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable)) throw error;
      gpuProblem = `${error.message} Grading needs WebGL2 with float render targets.`;
    }
  };
  startGpu();
  const onLost = (event) => { event.preventDefault(); lost = true; ctx.invalidate(); };
  const onRestored = () => {
    lost = false;
    if (context) disposeMethodsGpu(context.gl);
    gpu = context ? methodsGpu(context.gl) : null;
    painter = context ? createSpherePainter(context.gl) : null; // the old programs went with the context
    sourceKey = '';
    ctx.invalidate();
  };
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);

  const exercise = () => exerciseById(values.exercise);
  const code = () => values.code || exercise().start;
  const casesCache = new Map();
  const casesOf = (ex) => {
    if (!casesCache.has(ex.id)) casesCache.set(ex.id, ex.kind === 'conductor' ? conductorCases(exerciseMetal(ex)) : dielectricCases());
    return casesCache.get(ex.id);
  };
  const mapGrid = classify('exact-cg', 'fp64', MAP_GRID); // the grid (and the float64 map, all fine)

  let typing = 0;
  const editor = createCodeEditor(dom.editor, {
    doc: code(),
    label: 'GLSL code of the Fresnel function',
    onChange(text) {
      clearTimeout(typing);
      // Graded a moment after typing stops, not at every key.
      typing = window.setTimeout(() => ctx.set({ code: text === exercise().start ? '' : text }, { source: 'user' }), 400);
    },
    onRun() {
      clearTimeout(typing);
      const text = editor.text();
      ctx.set({ code: text === exercise().start ? '' : text });
    },
  });
  ctx.tie({ enable: (on) => editor.setReadOnly(!on), show: (on) => { dom.editor.hidden = !on; } }, ['code']);
  dom.grade.addEventListener('click', () => { editor.focus(); ctx.set({ code: editor.text() === exercise().start ? '' : editor.text() }); });
  dom.restart.addEventListener('click', () => ctx.set({ code: '' }));
  dom.reference.addEventListener('click', () => ctx.set({ code: exercise().reference }));
  for (const b of [dom.restart, dom.reference]) ctx.tie({ enable: (on) => { b.disabled = !on; }, show: (on) => { b.hidden = !on || (b === dom.reference && values.homework); } }, ['code']);

  /** @type {{ results: any[], summary: any, errors: any[], values: Record<string, Float32Array>, maps: { student: any, reference: any } }} */
  let state = { results: [], summary: null, errors: [], values: {}, maps: { student: null, reference: null } };
  let sourceKey = '';

  /** Evaluates `text` as the exercise's function over `inputs` in each precision; throws ShaderCompileFailed. */
  function evaluate(ex, text, key, { inputs, extra = null }) {
    const channels = ex.kind === 'conductor' ? 3 : 1;
    return Object.fromEntries(PRECISIONS.map((precision) => [precision, gpu.evaluateSource({
      key: `${key}|${precision}`, source: studentFragment(text, { kind: ex.kind, precision }), inputs, extra, channels,
    })]));
  }

  function gradeNow() {
    const ex = exercise();
    const text = code();
    const refused = checkStudentCode(text);
    state = { results: [], summary: null, errors: refused, values: {}, maps: { student: null, reference: null } };
    spheresProblem = 'No spheres until the code compiles and runs.';
    if (refused.length || !gpu || lost) return;
    const key = `student-${hashSeed(`${ex.id}\n${text}`).toString(36)}`;
    if (key !== sourceKey) gpu.forget('student-'); // only the newest code's programs are kept
    sourceKey = key;
    const cases = casesOf(ex);
    try {
      state.values = evaluate(ex, text, key, caseInputs(cases));
      if (ex.kind === 'dielectric') {
        const grid = { inputs: gridInputs(mapGrid) };
        const at = values.precision;
        const studentMap = evaluate(ex, text, `${key}-map`, grid)[at];
        const referenceMap = evaluate(ex, ex.reference, `reference-${ex.id}-map`, grid)[at];
        state.maps = {
          student: classifyGrid(studentMap, mapGrid, { methodId: 'student', precision: at }),
          reference: classifyGrid(referenceMap, mapGrid, { methodId: 'reference', precision: at }),
        };
      }
    } catch (error) {
      if (!(error instanceof ShaderCompileFailed)) throw error;
      state.errors = readCompileLog(error.log, ex.signature);
      if (!state.errors.length) state.errors = [{ line: null, message: error.message }];
      return;
    } finally {
      ctx.frameDrawn();
    }
    state.results = gradeExercise(ex, cases, (p) => state.values[p]);
    state.summary = errorSummary(cases, state.values.highp);
    paint();
  }

  let spheresProblem = 'No spheres until the code compiles and runs.';
  function paint() {
    if (!painter || state.errors.length || !state.summary) return;
    const ex = exercise();
    try {
      painter.paint(dom.spheresCanvas, `${sourceKey}|${ex.id}`, code(), ex, exerciseMetal(ex));
      spheresProblem = '';
    } catch (error) {
      if (!(error instanceof ShaderError)) throw error;
      // It compiled alone but not beside the page's lighting code: a name of the student's is taken.
      spheresProblem = 'The spheres could not be drawn: a name in your code is one the page’s lighting code uses (environment, skyLight, castStage, linearToSrgb…).';
    }
    ctx.frameDrawn();
  }

  function show() {
    const ex = exercise();
    dom.setTask(ex, ex.criteria.map((id, i) => ({ ...criterion(id), result: state.results[i] ?? null })));
    editor.setErrors(state.errors.filter((e) => e.line !== null));
    dom.setErrors(state.errors);
    dom.reference.hidden = values.homework;
    const problem = lost ? 'The graphics context was lost; grading resumes when it is back.' : gpuProblem;
    if (problem) dom.setSummary(problem);
    else if (state.summary) {
      const passed = state.results.filter((r) => r.pass).length;
      dom.setSummary(`${passed} of ${state.results.length} criteria pass. Against the exact R (highp): largest error ${sci(state.summary.max)} at ${state.summary.where}; mean ${sci(state.summary.mean)}.`);
    } else dom.setSummary(state.errors.length ? 'Not graded: see what stopped it above.' : '');
    const probe = gpu?.probePrecision();
    dom.setNote(ex.criteria.some((id) => criterion(id).precision === 'mediump') && probe?.mediumpIsFullPrecision
      ? 'This GPU runs mediump at full float32 precision, so the mediump criteria cannot fail here; on a phone with half precision they can.' : '');
    dom.maps.hidden = ex.kind !== 'dielectric';
    dom.setSpheresMessage(state.summary && !spheresProblem ? '' : spheresProblem || 'No spheres until the code compiles and runs.');
    dom.spheresCanvas.setAttribute('aria-label', ex.kind === 'conductor'
      ? 'Two gold spheres reflecting the sky: left with your function, right with the exact conductor Fresnel.'
      : 'Two red spheres under a clear coat of n = 1.5: left with your function, right with the exact Fresnel reflectance.');
    for (const side of ['student', 'reference']) {
      const figure = side === 'student' ? dom.student : dom.referenceMap;
      const map = state.maps[side];
      figure.setTitle(side === 'student' ? `Your function · ${values.precision}` : `A reference answer · ${values.precision}`, false);
      figure.setCounts(map);
      figure.showMessage(map ? '' : 'No map until the code compiles and runs.');
      figure.canvas.setAttribute('aria-label', map ? `Stability map of ${side === 'student' ? 'your function' : 'a reference answer'}: ${map.width * map.height - map.counts.fine} of ${map.width * map.height} cells fail` : 'No map');
      if (map) drawMap(figure.canvas, map, null);
    }
  }

  let started = false;
  function update(keys = []) {
    if (keys.includes('exercise') && !keys.includes('code')) {
      const next = stored(values.exercise) ?? ''; // each exercise keeps its own code
      if (next !== values.code) {
        ctx.set({ code: next }); // the host updates again with it
        return;
      }
    }
    // Kept in this browser as the student writes (a link's code is not stored until it is edited).
    if (started && keys.includes('code')) store(values.exercise, values.code);
    editor.setText(code());
    gradeNow();
    show();
  }
  const redraw = () => show();
  window.addEventListener('fresnel-lab:theme', redraw);
  let resizing = 0;
  const resizeObserver = new ResizeObserver(() => {
    cancelAnimationFrame(resizing);
    resizing = requestAnimationFrame(() => { if (dom.spheresCanvas.width !== Math.round(dom.spheresCanvas.getBoundingClientRect().width * Math.min(2, window.devicePixelRatio || 1))) paint(); });
  });
  resizeObserver.observe(dom.spheres);
  update();
  started = true;

  return {
    get results() { return state.results; },
    get errors() { return state.errors; },
    get maps() { return state.maps; },
    editor,
    /** The grading context (for tests that lose and restore it), or null. */
    get gl() { return context?.gl ?? null; },
    update,
    describe() {
      const ex = exercise();
      if (gpuProblem) return `${ex.title}: ${gpuProblem}`;
      if (state.errors.length) return `${ex.title}: not graded; ${state.errors.map((e) => (e.line ? `line ${e.line}: ${e.message}` : e.message)).join(' ')}`;
      if (!state.summary) return `${ex.title}: not graded yet.`;
      const passed = state.results.filter((r) => r.pass).length;
      const failing = state.results.filter((r) => !r.pass).map((r) => r.label);
      return `${ex.title}: ${passed} of ${state.results.length} criteria pass${failing.length ? ` (failing: ${failing.join('; ')})` : ''}. `
        + `Largest error against the exact R in highp ${sci(state.summary.max)} at ${state.summary.where}; mean ${sci(state.summary.mean)}.`;
    },
    csv() {
      const ex = exercise();
      const cases = casesOf(ex);
      const columns = { case: cases.map(caseText), cos: cases.map((c) => c.cos) };
      if (ex.kind === 'conductor') {
        ['red', 'green', 'blue'].forEach((name, ch) => {
          columns[`exact_${name}`] = cases.map((c) => c.exact[ch]);
          for (const p of PRECISIONS) columns[`yours_${p}_${name}`] = cases.map((_, i) => (state.values[p] ? state.values[p][i * 3 + ch] : ''));
        });
      } else {
        columns.nI = cases.map((c) => c.nI);
        columns.nT = cases.map((c) => c.nT);
        columns.exact = cases.map((c) => c.exact);
        for (const p of PRECISIONS) columns[`yours_${p}`] = cases.map((_, i) => (state.values[p] ? state.values[p][i] : ''));
      }
      return { filename: `shader-lab-${ex.id}.csv`, columns };
    },
    png() {
      /** @type {Array<{ side: 'student' | 'reference', figure: any, title: string }>} */
      const sides = [{ side: 'student', figure: dom.student, title: 'Your function' }, { side: 'reference', figure: dom.referenceMap, title: 'A reference answer' }];
      const parts = sides.filter(({ side }) => state.maps[side]).map(({ side, figure, title }) => ({ canvas: figure.canvas, title, map: state.maps[side] }));
      return parts.length ? composePng(parts, `${exercise().title} · ${values.precision}`) : null;
    },
    dispose() {
      clearTimeout(typing);
      cancelAnimationFrame(resizing);
      resizeObserver.disconnect();
      painter?.dispose();
      window.removeEventListener('fresnel-lab:theme', redraw);
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      editor.destroy();
      if (context) {
        disposeMethodsGpu(context.gl);
        context.dispose();
      }
    },
  };
}
