// @ts-check
// Panel `stability`: where each dielectric Fresnel method fails, over θ 0°–90° × n_i/n_t
// 0.4–2.5 (both axes linear), on this GPU (RGBA32F read-back, classified in JS) beside the
// JavaScript emulation (stabilityMap.classify). The precision picks the pair: GPU highp beside JS
// float32 (or float64), GPU mediump beside JS float16. Whether mediump really is half precision
// here is measured by rendering 1 + 2^-f, not taken from the driver, whose answer Safari/iOS has
// got wrong (webglfundamentals "WebGL Precision Issues").
import { WebGL2Unavailable } from '../../gl/contextBudget.js';
import { createContext } from '../../gl/createContext.js';
import { disposeMethodsGpu, GpuFloatUnavailable, gpuPrecisionInfo, methodsGpu, renewMethodsGpu } from '../../gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../gl/shaderError.js';
import { cellAt, classifyGrid, criticalAngleDeg, gridInputs } from '../../methods/classifyGrid.js';
import { methodById } from '../../methods/methods.js';
import { contextFor } from '../../methods/rounding.js';
import { classify, classifyValue, CLASS_NAMES } from '../../methods/stabilityMap.js';
import { buildStabilityDom } from './buildStabilityDom.js';
import { CLASS_LABELS } from '../shared/createMapFigure.js';
import { drawMap } from '../shared/drawMap.js';
import { composePng } from '../shared/composePng.js';
import './styles.css';
import { schema } from './schema.js';
import { readByPointer } from '../../ui/readByPointer.js';

export { schema };

/** The two maps a precision shows: the GPU qualifier, the JS context, and which one was chosen. */
export function pairFor(precision) {
  const half = precision === 'fp16' || precision === 'mediump';
  return {
    gpu: half ? 'mediump' : 'highp',
    js: precision === 'fp64' ? 'fp64' : half ? 'fp16' : 'fp32',
    selected: precision === 'highp' || precision === 'mediump' ? 'gpu' : 'js',
  };
}

const fmt = (v) => (Number.isFinite(v) ? v.toPrecision(6) : String(v));
const failing = (map) => map.width * map.height - map.counts.fine;

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildStabilityDom(root);
  let context = null;
  let gpu = null;
  let gpuProblem = '';
  let probe = null;
  let claimed = null;
  try {
    context = createContext(document.createElement('canvas'));
    gpu = methodsGpu(context.gl);
    probe = gpu.probePrecision();
    claimed = gpuPrecisionInfo(context.gl);
    ctx.frameDrawn();
  } catch (error) {
    if (error instanceof ShaderError) { // an unusual driver: the JavaScript map still stands
      console.error(error);
      gpu = null;
      gpuProblem = `This GPU could not compile the evaluation shader, so there is no GPU map: ${error.log.trim().split('\n')[0] || error.message}. The JavaScript map still works.`;
    } else if (error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable) {
      gpuProblem = `${error.message} The GPU map needs WebGL2 with float render targets; the JavaScript map still works.`;
    } else throw error;
  }

  // A lost context takes the evaluator's programs and textures with it; the values already read
  // back stay true, so only maps not yet evaluated wait for the restore, which makes the evaluator anew.
  let lost = false;
  const LOST = 'The graphics context was lost; the GPU map comes back when it is restored.';
  const onLost = (event) => {
    event.preventDefault();
    lost = true;
    ctx.invalidate();
  };
  const onRestored = () => {
    lost = false;
    gpuProblem = '';
    try {
      gpu = renewMethodsGpu(context.gl);
    } catch (error) {
      gpu = null;
      gpuProblem = `The GPU evaluator could not start again: ${error.message}`;
    }
    ctx.invalidate();
  };
  context?.gl.canvas.addEventListener('webglcontextlost', onLost);
  context?.gl.canvas.addEventListener('webglcontextrestored', onRestored);

  const folder = ctx.gui.addFolder('Map');
  ctx.bind(folder, ['method', 'precision', 'tolerance']);

  const gpuValues = new Map(); // 'method|qualifier' → Float32Array (independent of the tolerance)
  let maps = { gpu: null, js: null };
  let pair = pairFor(values.precision);
  let probeCell = null;
  const layouts = {};

  function gpuMap(grid) {
    if (!gpu) return null;
    const key = `${values.method}|${pair.gpu}`;
    if (!gpuValues.has(key)) {
      if (lost || context.gl.isContextLost()) {
        gpuProblem = LOST;
        return null;
      }
      try {
        gpuValues.set(key, gpu.evaluate({ methodId: values.method, precision: pair.gpu, inputs: gridInputs(grid) }));
      } catch (error) { // a lost context, say: the JavaScript map still stands
        gpuProblem = `The GPU evaluation failed: ${error.message}`;
        return null;
      }
      ctx.frameDrawn();
    }
    return { ...classifyGrid(gpuValues.get(key), grid, { methodId: values.method, precision: pair.gpu }), values: gpuValues.get(key) };
  }

  function note() {
    if (!gpu || !maps.gpu) return gpuProblem;
    const claim = claimed?.mediump ? ` (the driver claims ${claimed.mediump.precision + 1} bits; not trusted, measured instead)` : '';
    if (probe.mediumpIsFullPrecision) {
      return `mediump runs at full precision on this GPU: 1 + 2⁻¹² ≠ 1, ${probe.mediumpBits} significand bits${claim}. `
        + 'Its map matches highp; the JavaScript float16 map shows what a phone GPU with true half precision does.';
    }
    return `mediump runs at reduced precision on this GPU: ${probe.mediumpBits} significand bits (float16 has 11)${claim}.`;
  }

  function draw() {
    for (const side of ['gpu', 'js']) {
      if (maps[side]) layouts[side] = drawMap(dom[side].canvas, maps[side], probeCell);
    }
  }

  const fullMediump = () => Boolean(probe?.mediumpIsFullPrecision && pair.gpu === 'mediump');

  function sideTitle(side) {
    return side === 'gpu' ? `On this GPU · ${pair.gpu}` : `JavaScript · ${contextFor(pair.js).name}`;
  }

  function update() {
    pair = pairFor(values.precision);
    const method = methodById(values.method);
    maps.js = classify(values.method, pair.js, { tolerance: values.tolerance });
    maps.gpu = gpuMap(maps.js);
    dom.setNote(note());
    for (const side of ['gpu', 'js']) {
      const map = maps[side];
      dom[side].setTitle(sideTitle(side), pair.selected === side);
      dom[side].setCounts(map);
      if (map) {
        dom[side].canvas.setAttribute('aria-label', `Stability map of ${method.label}, ${sideTitle(side)}: `
          + `${failing(map)} of ${map.width * map.height} cells fail. Arrow keys move the probe.`);
      }
    }
    dom.gpu.showMessage(maps.gpu ? '' : gpuProblem);
    draw();
    readout();
  }

  function readout() {
    if (!probeCell || !maps.js) return dom.setReadout('');
    const cell = cellAt(maps.js, probeCell.i, probeCell.j);
    const method = methodById(values.method);
    const critical = criticalAngleDeg(cell.ratio);
    const parts = [`θ = ${cell.thetaDeg.toFixed(2)}°, n_i/n_t = ${cell.ratio.toFixed(3)}`
      + `${critical === null ? '' : ` (θc = ${critical.toFixed(2)}°)`}`, `exact R = ${fmt(cell.reference)}`];
    const k = cell.j * maps.js.width + cell.i;
    if (maps.gpu) parts.push(`GPU ${pair.gpu}: ${fmt(maps.gpu.values[k])} (${CLASS_LABELS[CLASS_NAMES[maps.gpu.cells[k]]]})`);
    const jsValue = method.evaluate(pair.js, cell.cos, cell.ratio, 1);
    const jsClass = CLASS_NAMES[classifyValue(jsValue, cell.reference, values.tolerance)];
    parts.push(`JS ${contextFor(pair.js).label}: ${fmt(jsValue)} (${CLASS_LABELS[jsClass]})`);
    dom.setReadout(parts.join(' · '));
  }

  function setProbe(cell) {
    probeCell = cell;
    draw();
    readout();
  }

  const onMove = (side) => (event) => {
    const rect = dom[side].canvas.getBoundingClientRect();
    const cell = layouts[side]?.cellAt(event.clientX - rect.left, event.clientY - rect.top);
    if (cell && (cell.i !== probeCell?.i || cell.j !== probeCell?.j)) setProbe(cell);
  };
  const onKey = (event) => {
    const map = maps.js;
    const cell = probeCell ?? { i: Math.floor(map.width / 2), j: Math.floor(map.height / 2) };
    const step = event.shiftKey ? 10 : 1;
    const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowDown: [0, -step], ArrowUp: [0, step], Home: [-map.width, 0], End: [map.width, 0] };
    if (!(event.key in moves)) return;
    event.preventDefault();
    const [di, dj] = moves[event.key];
    setProbe({ i: Math.min(map.width - 1, Math.max(0, cell.i + di)), j: Math.min(map.height - 1, Math.max(0, cell.j + dj)) });
  };
  const listeners = ['gpu', 'js'].map((side) => {
    dom[side].canvas.addEventListener('keydown', onKey);
    return [dom[side].canvas, readByPointer(dom[side].canvas, onMove(side))]; // the probe stays where it was read
  });
  const redraw = () => draw();
  const resizeObserver = new ResizeObserver(redraw);
  resizeObserver.observe(dom.maps);
  window.addEventListener('fresnel-lab:theme', redraw);
  update();

  return {
    get maps() { return maps; },
    get pair() { return pair; },
    /** The shared evaluator of this panel's context (createMethodsGpu's handle), or null. */
    get gpu() { return gpu; },
    /** This panel's WebGL2 context (its canvas is never on the page), or null. */
    get gl() { return context?.gl ?? null; },
    get precisionProbe() { return probe; },
    get probeCell() { return probeCell; },
    setProbe,
    /** The drawn colour [r, g, b, a] at the centre of cell (i, j) of one map ('gpu' | 'js'). */
    pixelAt(side, i, j) {
      const { canvas } = dom[side];
      const scale = canvas.width / canvas.getBoundingClientRect().width;
      const x = Math.floor(layouts[side].x(maps[side].thetaDeg[i]) * scale);
      const y = Math.floor(layouts[side].y(maps[side].ratio[j]) * scale);
      return [...canvas.getContext('2d').getImageData(x, y, 1, 1).data];
    },
    update,
    describe() {
      const method = methodById(values.method);
      const words = (map) => `${map.counts.fine} fine, ${map.counts.aboveTolerance} with error above ${values.tolerance.toPrecision(3)}, `
        + `${map.counts.outOfRange} outside [0, 1] and ${map.counts.notFinite} NaN or infinite`;
      const gpuText = maps.gpu ? `on this GPU in ${pair.gpu}: ${words(maps.gpu)}` : 'no GPU map (no float render targets)';
      const mediump = fullMediump() ? ' mediump runs at full precision on this GPU.' : '';
      return `${method.label} over ${maps.js.width} angles × ${maps.js.height} index ratios: ${gpuText}; `
        + `in JavaScript ${contextFor(pair.js).label}: ${words(maps.js)}.${mediump}`;
    },
    csv() {
      const columns = { class: [...CLASS_NAMES] };
      if (maps.gpu) columns[`gpu_${pair.gpu}`] = CLASS_NAMES.map((c) => maps.gpu.counts[c]);
      columns[`js_${pair.js}`] = CLASS_NAMES.map((c) => maps.js.counts[c]);
      return { filename: `stability-${values.method}-${values.precision}.csv`, columns };
    },
    png() {
      return composePng(['gpu', 'js'].filter((side) => maps[side])
        .map((side) => ({ canvas: dom[side].canvas, title: sideTitle(side), map: maps[side] })),
      `${methodById(values.method).label}${fullMediump() ? ' (mediump runs at full precision on this GPU)' : ''}`);
    },
    dispose() {
      resizeObserver.disconnect();
      window.removeEventListener('fresnel-lab:theme', redraw);
      for (const [canvas, stopReading] of listeners) {
        stopReading();
        canvas.removeEventListener('keydown', onKey);
      }
      if (context) {
        context.gl.canvas.removeEventListener('webglcontextlost', onLost);
        context.gl.canvas.removeEventListener('webglcontextrestored', onRestored);
        disposeMethodsGpu(context.gl);
        context.dispose();
      }
      gpuValues.clear();
      maps = { gpu: null, js: null };
    },
  };
}
