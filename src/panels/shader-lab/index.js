// @ts-check
// Panel `shader-lab`: the student writes the Fresnel function in GLSL; the page compiles it into a
// read-back shader on this GPU, evaluates it over the grading grid in highp and in mediump, reads
// the results back from a float target and grades them against the float64 core, criterion by
// criterion, with the worst case named; beside it, two spheres shaded with it and with the exact
// function, and the stability map of the student's function and of a reference answer. The
// grading and the GPU are runs.js's, what is said of them words.js's; this view holds the editor,
// its buttons and the code kept in the browser, and shows what the runs hold.
import { createReadBackGpu } from '../shared/createReadBackGpu.js';
import { drawMap } from '../shared/drawMap.js';
import { composePng } from '../shared/composePng.js';
import { buildShaderLabDom } from './buildShaderLabDom.js';
import { createCodeEditor } from './createCodeEditor.js';
import { createShaderLabRuns } from './runs.js';
import {
  codeErrors, criteriaRows, describeText, exerciseTitle, gradeCsv, mapLabel, mapMessage, mapTitle, noteText, readBackWords,
  spheresLabel, spheresMessage, summaryText,
} from './words.js';
import { createSpherePainter } from './paintSpheres.js';
import { readStored, writeStored } from './storedCode.js';
import { useDeflate } from './codeCodec.js';
import { deflateSync } from 'fflate';
import './styles.css';
import { schema } from './schema.js';
import english from 'virtual:messages/en/shader-lab';
import { messages } from '../../i18n/messages.js';

const t = messages('shader-lab', english);

export { schema };

useDeflate((bytes) => deflateSync(bytes, { level: 9 })); // the link's compact form, from now on

/** @typedef {import('./runs.js').MapSide} MapSide */

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildShaderLabDom(root);
  // Homework mode comes from the link or a message only: a student cannot switch it off here.
  ctx.bind(ctx.gui.addFolder(t('folder')), ['exercise', 'precision']);
  // A link or a message without code: the code this browser kept for the exercise, if any.
  if (!values.code && readStored(values.exercise)) ctx.set({ code: readStored(values.exercise) });

  // One context for the grading and the spheres (painted there, copied to a 2D canvas on the page).
  const gpu = createReadBackGpu({
    words: readBackWords, prepare: (_evaluator, gl) => createSpherePainter(gl), onChange: () => ctx.invalidate(),
  });
  const runs = createShaderLabRuns({ values, gpu, onRead: () => ctx.frameDrawn() });

  // What the student types is graded a moment after typing stops, and kept in this browser.
  let typing = 0;
  const submit = (text) => {
    clearTimeout(typing);
    typing = 0;
    const value = text === runs.exercise().start ? '' : text;
    writeStored(values.exercise, value);
    ctx.set({ code: value });
  };
  const editor = createCodeEditor(dom.editor, {
    doc: runs.code(),
    label: t('editorLabel'),
    onChange(text) {
      clearTimeout(typing);
      typing = window.setTimeout(() => submit(text), 400);
    },
    onRun() {
      runs.retry(); // asked for: graded even if it stalled the GPU before
      submit(editor.text());
    },
  });
  let codeShown = true;
  const showButtons = () => {
    dom.restart.hidden = !codeShown;
    dom.reference.hidden = !codeShown || values.homework;
  };
  ctx.tie({ enable: (on) => editor.setReadOnly(!on), show: (on) => { dom.editor.hidden = !on; } }, ['code']);
  const buttons = {
    enable: (on) => { dom.restart.disabled = !on; dom.reference.disabled = !on; },
    show: (on) => { codeShown = on; showButtons(); },
  };
  ctx.tie(buttons, ['code']);
  dom.grade.addEventListener('click', () => { runs.retry(); submit(editor.text()); editor.focus(); });
  dom.restart.addEventListener('click', () => submit(runs.exercise().start));
  dom.reference.addEventListener('click', () => ctx.set({ code: runs.exercise().reference }));

  const figures = /** @type {Record<MapSide, typeof dom.student>} */ ({ student: dom.student, reference: dom.referenceMap });

  function show() {
    const ex = runs.exercise();
    const { state } = runs;
    const errors = codeErrors(runs);
    dom.setTask({ title: exerciseTitle(ex), signature: ex.signature }, criteriaRows(runs));
    editor.setErrors(errors.filter((e) => e.line !== null));
    dom.setErrors(errors);
    showButtons();
    dom.setSummary(summaryText(runs));
    dom.setNote(noteText(runs));
    dom.maps.hidden = ex.kind !== 'dielectric';
    dom.setSpheresMessage(spheresMessage(runs));
    dom.spheresCanvas.setAttribute('aria-label', spheresLabel(runs));
    for (const side of /** @type {MapSide[]} */ (['student', 'reference'])) {
      const figure = figures[side];
      const map = state.maps[side];
      figure.setTitle(mapTitle(values, side), false);
      figure.setCounts(map);
      figure.showMessage(mapMessage(runs, side));
      figure.canvas.setAttribute('aria-label', mapLabel(runs, side));
      if (map) drawMap(figure.canvas, map, null);
    }
    // After the canvas is shown, so it is painted at its own size.
    if (runs.paint(dom.spheresCanvas)) dom.setSpheresMessage(spheresMessage(runs));
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
      editor.setText(runs.code(), { history: !keys.includes('exercise') });
    }
    runs.update();
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
    get results() { return runs.state.results; },
    get errors() { return codeErrors(runs); },
    get maps() { return runs.state.maps; },
    editor,
    runs,
    /** The grading context (for tests that lose and restore it), or null. */
    get gl() { return gpu.gl; },
    update,
    describe: () => describeText(runs),
    csv: () => gradeCsv(runs),
    png() {
      const { state } = runs;
      const sides = /** @type {Array<{ side: MapSide, title: string }>} */ ([
        { side: 'student', title: t('yourFunction') }, { side: 'reference', title: t('referenceAnswer') },
      ]);
      const parts = sides.filter(({ side }) => state.maps[side])
        .map(({ side, title }) => ({ canvas: figures[side].canvas, title, map: state.maps[side] }));
      const caption = t('pngCaption', { exercise: exerciseTitle(runs.exercise()), precision: values.precision });
      if (parts.length) return composePng(parts, caption);
      return state.summary && !state.spheres ? dom.spheresCanvas.toDataURL('image/png') : null; // the conductor: its spheres
    },
    dispose() {
      if (typing) writeStored(values.exercise, editor.text() === runs.exercise().start ? '' : editor.text()); // nothing typed is lost
      clearTimeout(typing);
      cancelAnimationFrame(resizing);
      resizeObserver.disconnect();
      window.removeEventListener('fresnel-lab:theme', redraw);
      editor.destroy();
      runs.dispose();
    },
  };
}
