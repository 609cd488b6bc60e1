// @ts-check
// Panel `stability`: where each dielectric Fresnel method fails, over θ 0°–90° × n_i/n_t
// 0.4–2.5 (both axes linear), on this GPU (RGBA32F read-back, classified in JS) beside the
// JavaScript emulation (stabilityMap.classify). The precision picks the pair: GPU highp beside JS
// float32 (or float64), GPU mediump beside JS float16. The state and the read-back are runs.js's,
// what is said of them words.js's; this view draws the maps, shows the words and moves the probe.
import { buildStabilityDom } from './buildStabilityDom.js';
import { createStabilityRuns, pairFor } from './runs.js';
import {
  describeText, gpuMessage, mapLabel, mapsCsv, noteText, pngCaption, readBackWords, readoutText, sideTitle,
} from './words.js';
import { createReadBackGpu } from '../shared/createReadBackGpu.js';
import { drawMap } from '../shared/drawMap.js';
import { composePng } from '../shared/composePng.js';
import './styles.css';
import { schema } from './schema.js';
import { readByPointer } from '../../ui/readByPointer.js';
import english from 'virtual:messages/en/stability';
import { messages } from '../../i18n/messages.js';

const t = messages('stability', english);

export { schema, pairFor };

/** @typedef {import('./runs.js').Side} Side */
const SIDES = /** @type {Side[]} */ (['gpu', 'js']);

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const dom = buildStabilityDom(root);
  // A lost context takes the evaluator with it; the maps already read back stay true, so only maps
  // not yet evaluated wait for the restore (createReadBackGpu makes the evaluator anew then).
  const gpu = createReadBackGpu({ words: readBackWords, onChange: () => ctx.invalidate() });
  const runs = createStabilityRuns({ values: ctx.values, gpu, onRead: () => ctx.frameDrawn() });
  ctx.bind(ctx.gui.addFolder(t('folder')), ['method', 'precision', 'tolerance']);

  /** @type {Partial<Record<Side, ReturnType<typeof drawMap>>>} */
  const layouts = {};
  function draw() {
    for (const side of SIDES) {
      if (runs.maps[side]) layouts[side] = drawMap(dom[side].canvas, runs.maps[side], runs.probeCell);
    }
  }
  function showProbe() {
    draw();
    dom.setReadout(readoutText(runs));
  }

  function update() {
    runs.update();
    dom.setNote(noteText(runs));
    for (const side of SIDES) {
      dom[side].setTitle(sideTitle(runs.pair, side), runs.pair.selected === side);
      dom[side].setCounts(runs.maps[side]);
      const label = mapLabel(ctx.values, runs, side);
      if (label) dom[side].canvas.setAttribute('aria-label', label);
    }
    dom.gpu.showMessage(gpuMessage(runs));
    showProbe();
  }

  function setProbe(cell) {
    runs.setProbe(cell);
    showProbe();
  }
  const onMove = (side) => (event) => {
    const rect = dom[side].canvas.getBoundingClientRect();
    const cell = layouts[side]?.cellAt(event.clientX - rect.left, event.clientY - rect.top);
    const probed = runs.probeCell;
    if (cell && (cell.i !== probed?.i || cell.j !== probed?.j)) setProbe(cell);
  };
  const onKey = (event) => {
    if (!runs.moveProbe(event.key, event.shiftKey)) return;
    event.preventDefault();
    showProbe();
  };
  const listeners = SIDES.map((side) => {
    dom[side].canvas.addEventListener('keydown', onKey);
    // The probe stays where it was read.
    return /** @type {const} */ ([dom[side].canvas, readByPointer(dom[side].canvas, onMove(side))]);
  });
  const redraw = () => draw();
  const resizeObserver = new ResizeObserver(redraw);
  resizeObserver.observe(dom.maps);
  window.addEventListener('fresnel-lab:theme', redraw);
  update();

  return {
    get maps() { return runs.maps; },
    get pair() { return runs.pair; },
    /** The method evaluator on this panel's context (createMethodsGpu's handle), or null. */
    get gpu() { return gpu.evaluator; },
    /** This panel's WebGL2 context (its canvas is never on the page), or null. */
    get gl() { return gpu.gl; },
    get precisionProbe() { return runs.precisionProbe; },
    get probeCell() { return runs.probeCell; },
    runs,
    setProbe,
    /** The drawn colour [r, g, b, a] at the centre of cell (i, j) of one map ('gpu' | 'js'). */
    pixelAt(side, i, j) {
      const { canvas } = dom[side];
      const scale = canvas.width / canvas.getBoundingClientRect().width;
      const x = Math.floor(layouts[side].x(runs.maps[side].thetaDeg[i]) * scale);
      const y = Math.floor(layouts[side].y(runs.maps[side].ratio[j]) * scale);
      return [...canvas.getContext('2d').getImageData(x, y, 1, 1).data];
    },
    update,
    describe: () => describeText(ctx.values, runs),
    csv: () => mapsCsv(ctx.values, runs),
    png() {
      const parts = SIDES.filter((side) => runs.maps[side])
        .map((side) => ({ canvas: dom[side].canvas, title: sideTitle(runs.pair, side), map: runs.maps[side] }));
      return composePng(parts, pngCaption(ctx.values, runs));
    },
    dispose() {
      resizeObserver.disconnect();
      window.removeEventListener('fresnel-lab:theme', redraw);
      for (const [canvas, stopReading] of listeners) {
        stopReading();
        canvas.removeEventListener('keydown', onKey);
      }
      runs.dispose();
    },
  };
}
