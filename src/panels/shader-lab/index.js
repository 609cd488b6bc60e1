// @ts-check
// Panel `shader-lab`: the student writes the Fresnel function in GLSL; the page compiles it into a
// read-back shader on this GPU, evaluates it over the grading grid in highp and in mediump, reads
// the results back from a float target and grades them against the float64 core, criterion by
// criterion, with the worst case named; beside it, two spheres shaded with it and with the exact
// function, and the stability map of the student's function and of a reference answer. The code is
// only ever compiled by the GPU driver, never run as JavaScript (studentShader.js refuses loops,
// directives and line continuations first).
import { WebGL2Unavailable } from '../../gl/contextBudget.js';
import { createContext } from '../../gl/createContext.js';
import { GpuFloatUnavailable, createMethodsGpu } from '../../gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../gl/shaderError.js';
import { classifyGrid, gridInputs } from '../../methods/classifyGrid.js';
import { classify } from '../../methods/stabilityMap.js';
import { drawMap } from '../shared/drawMap.js';
import { composePng } from '../shared/composePng.js';
import { buildShaderLabDom } from './buildShaderLabDom.js';
import { createCodeEditor } from './createCodeEditor.js';
import { caseInputs, caseText, conductorCases, dielectricCases } from './gradingCases.js';
import { criterion, exerciseById, exerciseMetal } from './exercises.js';
import { errorSummary, gradeExercise } from './gradeExercise.js';
import { checkStudentCode, readCompileLog, studentFragment } from './studentShader.js';
import { createSpherePainter } from './paintSpheres.js';
import { readStored, writeStored } from './storedCode.js';
import { useDeflate } from './codeCodec.js';
import { deflateSync } from 'fflate';
import './styles.css';
import { schema } from './schema.js';

export { schema };

useDeflate((bytes) => deflateSync(bytes, { level: 9 })); // the link's compact form, from now on

const PRECISIONS = ['highp', 'mediump'];
const MAP_GRID = { width: 91, height: 54 }; // θ every 1°, n_i/n_t from 0.4 to 2.5
const LOST = 'The graphics context was lost; grading resumes when it is back.';
const sci = (x) => (Number.isFinite(x) ? x.toExponential(2).replace('-', '−') : 'NaN');

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildShaderLabDom(root);
  // Homework mode comes from the link or a message only: a student cannot switch it off here.
  ctx.bind(ctx.gui.addFolder('Exercise'), ['exercise', 'precision']);
  // A link or a message without code: the code this browser kept for the exercise, if any.
  if (!values.code && readStored(values.exercise)) ctx.set({ code: readStored(values.exercise) });

  const canvas = document.createElement('canvas');
  let context = null;
  let gpu = null;
  let painter = null;
  let gpuProblem = '';
  let lost = false;
  try {
    context = createContext(canvas);
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
    gpuProblem = `${error.message} Grading needs WebGL2 with float render targets.`;
  }
  /** The evaluator and the sphere painter of the context, made anew after a loss (its programs went with it). */
  const startGpu = () => {
    gpu = null;
    painter = null;
    if (!context) return;
    try {
      gpu = createMethodsGpu(context.gl);
      painter = createSpherePainter(context.gl);
    } catch (error) {
      if (error instanceof ShaderError) { // the lab's own shaders, on an unusual driver
        console.error(error);
        gpu = null;
        painter = null;
        gpuProblem = `This GPU could not compile the lab’s own shaders, so nothing can be graded here: ${String(error.message).split('\n').find((l) => /ERROR/.test(l))?.trim() || error.message.split('\n')[0]}.`;
        return;
      }
      if (!(error instanceof GpuFloatUnavailable)) throw error;
      gpuProblem = `${error.message} Grading needs WebGL2 with float render targets.`;
    }
  };
  startGpu();
  // Code whose grading was under way when the context went: it may be what stopped the GPU, so it
  // is not graded again by itself (the Grade button still does).
  let stalled = null;
  let grading = null;
  const onLost = (event) => {
    event.preventDefault();
    lost = true;
    stalled = grading;
    ctx.invalidate();
  };
  const onRestored = () => {
    lost = false;
    startGpu();
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
  const mapInputs = { inputs: gridInputs(mapGrid) };
  const referenceMaps = new Map(); // 'exercise|precision' → map: the reference answer does not change

  // What the student types is graded a moment after typing stops, and kept in this browser.
  let typing = 0;
  const submit = (text) => {
    clearTimeout(typing);
    typing = 0;
    const value = text === exercise().start ? '' : text;
    writeStored(values.exercise, value);
    ctx.set({ code: value });
  };
  const editor = createCodeEditor(dom.editor, {
    doc: code(),
    label: 'GLSL code of the Fresnel function',
    onChange(text) {
      clearTimeout(typing);
      typing = window.setTimeout(() => submit(text), 400);
    },
    onRun() {
      stalled = null; // asked for: graded even if it stalled the GPU before
      submit(editor.text());
    },
  });
  let codeShown = true;
  const showButtons = () => {
    dom.restart.hidden = !codeShown;
    dom.reference.hidden = !codeShown || values.homework;
  };
  ctx.tie({ enable: (on) => editor.setReadOnly(!on), show: (on) => { dom.editor.hidden = !on; } }, ['code']);
  ctx.tie({ enable: (on) => { dom.restart.disabled = !on; dom.reference.disabled = !on; }, show: (on) => { codeShown = on; showButtons(); } }, ['code']);
  dom.grade.addEventListener('click', () => { stalled = null; submit(editor.text()); editor.focus(); });
  dom.restart.addEventListener('click', () => submit(exercise().start));
  dom.reference.addEventListener('click', () => ctx.set({ code: exercise().reference }));

  /** @type {{ results: any[], summary: any, errors: any[], values: Record<string, Float32Array>, maps: { student: any, reference: any }, spheres: string }} */
  let state = { results: [], summary: null, errors: [], values: {}, maps: { student: null, reference: null }, spheres: '' };
  let studentSource = '';

  /** The exercise's function in `text` over `inputs` in one precision; throws ShaderError. */
  function evaluate(ex, text, role, precision, { inputs, extra = null }) {
    return gpu.evaluateSource({
      key: `${role}|${ex.kind}|${precision}|${text}`, // the source itself: no two codes share a program
      source: studentFragment(text, { kind: ex.kind, precision }),
      inputs,
      extra,
      channels: ex.kind === 'conductor' ? 3 : 1,
    });
  }

  function gradeNow() {
    const ex = exercise();
    const text = code();
    const refused = checkStudentCode(text);
    state = { results: [], summary: null, errors: refused, values: {}, maps: { student: null, reference: null }, spheres: 'No spheres until the code compiles and runs.' };
    if (refused.length || !gpu || lost) return;
    if (stalled === text) {
      state.errors = [{ line: null, message: 'The graphics card stopped responding while this code was graded, and the browser reset it. Change the code, or press Grade to try it once more.' }];
      return;
    }
    if (text !== studentSource) gpu.forget('student|'); // only the newest code's programs are kept
    studentSource = text;
    const cases = casesOf(ex);
    grading = text;
    try {
      const inputs = caseInputs(cases);
      for (const precision of PRECISIONS) state.values[precision] = evaluate(ex, text, 'student', precision, inputs);
      if (ex.kind === 'dielectric') {
        const at = values.precision;
        const refKey = `${ex.id}|${at}`;
        if (!referenceMaps.has(refKey)) {
          referenceMaps.set(refKey, classifyGrid(evaluate(ex, ex.reference, 'reference', at, mapInputs), mapGrid, { methodId: 'reference', precision: at }));
        }
        state.maps = {
          student: classifyGrid(evaluate(ex, text, 'student', at, mapInputs), mapGrid, { methodId: 'student', precision: at }),
          reference: referenceMaps.get(refKey),
        };
      }
    } catch (error) {
      if (error instanceof ShaderError) {
        state.errors = readCompileLog(error.log, ex.signature);
        if (!state.errors.length) state.errors = [{ line: null, message: error.message }];
        return;
      }
      if (context?.gl.isContextLost()) { lost = true; return; } // the event is still to come
      throw error;
    } finally {
      grading = null;
      ctx.frameDrawn();
    }
    state.results = gradeExercise(ex, cases, (p) => state.values[p]);
    state.summary = errorSummary(cases, state.values.highp);
    state.spheres = '';
  }

  function paint() {
    if (!painter || lost || state.spheres || !state.summary) return;
    const ex = exercise();
    try {
      painter.paint(dom.spheresCanvas, code(), ex, exerciseMetal(ex));
    } catch (error) {
      if (!(error instanceof ShaderError)) throw error;
      // It compiled alone but not beside the page's lighting code: say what the driver said.
      const first = String(error.message).split('\n').find((l) => /ERROR/.test(l))?.trim() ?? '';
      state.spheres = `The spheres could not be drawn beside the page’s lighting code: ${first || 'the shader did not compile'} (is one of your names environment, skyLight, castStage or linearToSrgb?).`;
      dom.setSpheresMessage(state.spheres);
    }
  }

  function show() {
    const ex = exercise();
    dom.setTask(ex, ex.criteria.map((id, i) => ({ ...criterion(id), result: state.results[i] ?? null })));
    editor.setErrors(state.errors.filter((e) => e.line !== null));
    dom.setErrors(state.errors);
    showButtons();
    const problem = lost ? LOST : gpuProblem;
    if (problem) dom.setSummary(problem);
    else if (state.summary) {
      const passed = state.results.filter((r) => r.pass).length;
      dom.setSummary(`${passed} of ${state.results.length} criteria pass. Against the exact R (highp): largest error ${sci(state.summary.max)} at ${state.summary.where}; mean ${sci(state.summary.mean)}.`);
    } else dom.setSummary(state.errors.length ? 'Not graded: see what stopped it above.' : '');
    let fullMediump = false;
    try {
      fullMediump = Boolean(gpu && !lost && gpu.probePrecision().mediumpIsFullPrecision);
    } catch { /* a context lost between the event and here: the next update says so */ }
    dom.setNote(ex.criteria.some((id) => criterion(id).precision === 'mediump') && fullMediump
      ? 'This GPU runs mediump at full float32 precision, so the mediump criteria cannot fail here; on a phone with half precision they can.' : '');
    dom.maps.hidden = ex.kind !== 'dielectric';
    const waiting = lost ? LOST : 'No map until the code compiles and runs.';
    dom.setSpheresMessage(lost ? LOST : state.spheres);
    dom.spheresCanvas.setAttribute('aria-label', ex.kind === 'conductor'
      ? 'Two gold spheres reflecting the sky: the first with your function, the second with the exact conductor Fresnel.'
      : 'Two red spheres under a clear coat of n = 1.5: the first with your function, the second with the exact Fresnel reflectance.');
    for (const side of ['student', 'reference']) {
      const figure = side === 'student' ? dom.student : dom.referenceMap;
      const map = state.maps[side];
      figure.setTitle(side === 'student' ? `Your function · ${values.precision}` : `A reference answer · ${values.precision}`, false);
      figure.setCounts(map);
      figure.showMessage(map ? '' : waiting);
      figure.canvas.setAttribute('aria-label', map ? `Stability map of ${side === 'student' ? 'your function' : 'a reference answer'}: ${map.width * map.height - map.counts.fine} of ${map.width * map.height} cells fail` : 'No map');
      if (map) drawMap(figure.canvas, map, null);
    }
    paint(); // after the canvas is shown, so it is painted at its own size
  }

  function update(keys = []) {
    if (keys.includes('exercise') && !keys.includes('code')) {
      const next = readStored(values.exercise) ?? ''; // each exercise keeps its own code
      if (next !== values.code && ctx.set({ code: next }).changed.includes('code')) return; // the host updates again with it
    }
    // The editor follows the value when the value changed (not on every update: typing goes on).
    if (!keys.length || keys.includes('code') || keys.includes('exercise')) {
      clearTimeout(typing);
      typing = 0;
      editor.setText(code(), { history: !keys.includes('exercise') });
    }
    gradeNow();
    show();
  }
  const redraw = () => show();
  window.addEventListener('fresnel-lab:theme', redraw);
  let resizing = 0;
  const resizeObserver = new ResizeObserver(() => {
    cancelAnimationFrame(resizing);
    resizing = requestAnimationFrame(redraw);
  });
  resizeObserver.observe(dom.spheres);
  resizeObserver.observe(dom.maps);
  update();

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
      if (lost) return `${ex.title}: ${LOST}`;
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
      if (parts.length) return composePng(parts, `${exercise().title} · ${values.precision}`);
      return state.summary && !state.spheres ? dom.spheresCanvas.toDataURL('image/png') : null; // the conductor: its spheres
    },
    dispose() {
      if (typing) writeStored(values.exercise, editor.text() === exercise().start ? '' : editor.text()); // nothing typed is lost
      clearTimeout(typing);
      cancelAnimationFrame(resizing);
      resizeObserver.disconnect();
      painter?.dispose();
      window.removeEventListener('fresnel-lab:theme', redraw);
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      editor.destroy();
      gpu?.dispose();
      context?.dispose();
    },
  };
}
