// @ts-check
// Panel `speed-accuracy`: every Fresnel method as a point, cost against worst display error, for a
// scene (domain and precision from scenes.js), with the Pareto front, the chosen budget as a line,
// and the advisor's pick (advisor.recommend via displayBudgets.recommendWithin) with its reason.
// Costs are the static SPIR-V instruction counts (computed; see methods.js) until "Run benchmark"
// measures them on this device (GPU ns per evaluation at the scene's precision, or CPU ns).
// Errors come from the JS emulation at the scene's precision, or ("Error measured by") from this
// GPU in highp or mediump: every sample rendered and read back (measureGpuErrors.js, gpuErrors.js).
// ?bench=normal|tiny runs the benchmark on load (npm run bench uses it).
import { benchCsv, benchResults, benchTable, gpuPrecisionFor, measuredCosts } from '../../methods/benchResults.js';
import {
  CRITERION, displayBudget, meanDisplayCodes, recommendWithin,
} from '../../methods/displayBudgets.js';
import { recommendWithErrors } from '../../methods/gpuErrors.js';
import { toDegrees } from '../../optics/angles.js';
import { methodById } from '../../methods/methods.js';
import { paretoFront } from '../../methods/paretoFront.js';
import { sceneById } from '../../methods/scenes.js';
import { downloadText } from '../../host/exporters.js';
import { createVisibilityGate } from '../../ui/createVisibilityGate.js';
import { BENCH_SIZES, loadCachedResults, runBenchmark, saveCachedResults } from './runBenchmark.js';
import { createScatter } from './createScatter.js';
import { buildSpeedAccuracyDom, formatCodes, formatNs } from './buildSpeedAccuracyDom.js';
import { cachedGpuErrors, gpuPrecisionProbe, measureGpuErrors } from './measureGpuErrors.js';
import {
  glslOf, mediumpNote, PRECISION_WORDS, sourceWords,
} from './errorSources.js';
import './styles.css';
import { schema } from './schema.js';

export { schema };

function caseText(kind, args) {
  if (!args) return '';
  return kind === 'dielectric' ? `n ${args[0]} → ${+args[1].toFixed(3)}` : `n ${args[0]}, k ${args[1]}`;
}

/**
 * The cheaper pick under the "acceptable" budget (5 % of the range, the judgement behind the
 * Schlick that Filament, Godot, three.js and UE4 ship; see displayBudgets.js), when it differs from the strict one, with its measured cost in error.
 */
function practicalNote(alt, rec, rows) {
  if (!alt?.invisible || alt.methodId === rec.methodId) return '';
  const row = rows.find((r) => r.methodId === alt.methodId);
  const where = row.thetaAtMax === null ? '' : ` at ${toDegrees(row.thetaAtMax).toFixed(1)}°`; // as the advisor's reason writes it
  return ` If a visible error of up to 5 % of the range is acceptable (the judgement behind the Schlick that engines ship), `
    + `${row.label} would do: ${formatCodes(row.maxCodes)} codes at worst${where}, ${formatCodes(row.meanCodes)} on average.`;
}

/** A warning when timings overlap so much that their order is not to be trusted. */
function noiseNote(rows) {
  const noisy = rows.filter((r) => Number.isFinite(r.xMin) && (r.xMax - r.xMin > Math.abs(r.x) || r.x <= 0));
  return noisy.length ? ` ${noisy.length} of ${rows.length} timings vary by more than their median (or are ≤ 0): `
    + 'the machine was busy, so the order of close methods is uncertain; run again when it is idle.' : '';
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  let results = loadCachedResults();
  let controller = null;
  let running = null;
  let view = null; // the last drawn state, for describe() and csv()
  let measuring = null; // the GPU read-back under way: { key, promise }
  let gpuProblem = ''; // why the GPU read-back failed here, once it has
  let disposed = false;

  const dom = buildSpeedAccuracyDom(root, {
    onRun: () => { run('normal').catch(() => {}); },
    onCancel: () => controller?.abort(new DOMException('Benchmark cancelled', 'AbortError')),
    onJson: () => downloadText('fresnel-lab-speed-accuracy.json', `${JSON.stringify(currentResults(), null, 2)}\n`, 'application/json'),
  });
  // A run pauses between its steps while the panel is off screen, and says so.
  const gate = createVisibilityGate(root, {
    onPause: () => dom.setStatus('Paused while the panel is off screen; it goes on when you scroll back.'),
  });
  const chart = createScatter(dom.chartHost, {
    ariaLabel: 'Scatter of every Fresnel method: cost across, worst display error up (log scale), with the Pareto '
      + 'front and the error budget as a line. The table below lists the same numbers.',
  });
  const controllers = ctx.bind(ctx.gui.addFolder('Scene and budget'), ['scene', 'budget', 'errors', 'cost']);
  // Beside the "Error measured by" control: what mediump really is on this GPU, once measured.
  const gpuNote = document.createElement('p');
  gpuNote.className = 'sa-gui-note';
  gpuNote.setAttribute('role', 'status');
  controllers.errors.domElement.after(gpuNote);

  /** Results to export: the last run, or errors and static costs only. */
  const currentResults = () => results ?? benchResults({ meta: { date: new Date().toISOString() } });

  /** Starts reading a scene's errors back from the GPU (once per scene and precision per session). */
  function startMeasuring(scene, glsl) {
    const key = `${scene.id}|${glsl}`;
    if (measuring?.key === key) return;
    const promise = measureGpuErrors(scene, glsl).then(() => {
      if (measuring?.key === key) measuring = null;
      gpuProblem = '';
      if (!disposed) ctx.invalidate();
    }, (error) => {
      if (measuring?.key === key) measuring = null;
      if (disposed) return;
      gpuProblem = `${error?.message ?? error} Reading errors back needs WebGL2 with float render targets, `
        + 'so the errors shown are the JavaScript emulation.';
      if (glslOf(values.errors)) ctx.set({ errors: 'js' });
      else ctx.invalidate();
    });
    measuring = { key, promise };
  }

  /** The errors to plot: { source, glsl, measured (the GPU's, or null for JS), waiting }. */
  function errorSource(scene) {
    const glsl = glslOf(values.errors);
    if (!glsl) return { source: 'js', glsl: null, measured: null, waiting: null };
    const measured = cachedGpuErrors(scene, glsl);
    if (measured) return { source: values.errors, glsl, measured, waiting: null };
    startMeasuring(scene, glsl);
    return { source: 'js', glsl: null, measured: null, waiting: glsl };
  }

  function costOf(method, glsl, mode) {
    if (mode === 'static' || !results) return { x: method.cost.static, text: `${method.cost.static}` };
    const row = results.methods.find((m) => m.id === method.id);
    const spread = mode === 'cpu' ? row?.cpu?.nsPerEval : glsl === 'mediump' ? row?.gpu?.mediump?.nsPerEval : row?.gpu?.nsPerEval;
    if (!spread || !Number.isFinite(spread.median)) return null;
    return { x: spread.median, xMin: spread.min, xMax: spread.max, text: formatNs(spread) };
  }

  function update() {
    const scene = sceneById(values.scene);
    const budget = displayBudget(values.budget);
    const src = errorSource(scene);
    const glsl = src.glsl ?? gpuPrecisionFor(scene.precision); // GPU timings in the read-back's precision
    const wanted = values.cost;
    const costs = wanted === 'static' ? {} : measuredCosts(results, scene, wanted, glsl);
    const mode = Object.keys(costs).length > 0 ? wanted : 'static';
    const words = sourceWords(src.source, scene, src.measured?.device?.renderer);
    const recommendFor = (b) => (src.measured
      ? {
        ...recommendWithErrors(scene, src.measured.errors, costs, {
          budgetCodes: b.codes, where: `${scene.label}, this GPU in ${src.glsl} (read back)`, precision: src.glsl,
        }),
        budget: b,
        criterion: CRITERION,
      }
      : recommendWithin(scene, costs, b.id));
    const rec = recommendFor(budget);
    // Under a stricter budget, say what the "acceptable" judgement (what engines ship) would pick.
    const lenient = displayBudget('acceptable');
    const alt = budget.codes < lenient.codes ? recommendFor(lenient) : null;
    const rows = rec.table.map((r) => {
      const method = methodById(r.methodId);
      const cost = costOf(method, glsl, mode);
      return {
        ...r, ...cost, costText: cost.text, meanCodes: r.meanCodes ?? meanDisplayCodes(scene, method),
        caseText: caseText(scene.kind, r.caseAtMax), recommended: r.methodId === rec.methodId,
      };
    });
    const points = rows.map((r) => ({
      id: r.methodId, name: methodById(r.methodId).short, x: r.x, xMin: r.xMin, xMax: r.xMax, y: r.maxCodes, nan: !Number.isFinite(r.maxCodes),
      passes: r.passes, recommended: r.recommended,
    }));
    const front = paretoFront(points.map((p) => ({ x: p.x, y: p.nan ? Infinity : p.y })));
    rows.forEach((r, i) => { r.onFront = front.includes(i); });
    const unit = mode === 'static' ? 'static instruction count (SPIR-V)'
      : mode === 'cpu' ? 'CPU ns per evaluation (JS, float64; median, min–max)'
        : `GPU ns per evaluation, ${glsl} (median, min–max)`;
    chart.setData({
      points, front, budget: { codes: budget.codes, label: `${budget.codes} codes` },
      xLabel: `Cost: ${unit}`, yLabel: 'Worst display error, 8-bit codes (log)',
      title: `${scene.label}, ${words.short}`,
    });
    const chosen = rows.find((r) => r.recommended);
    const costNote = mode === 'static'
      ? (wanted === 'static' ? 'Costs: static instruction counts.' : 'Costs: static instruction counts until you run the benchmark.')
      : `Costs: measured here (${mode === 'cpu' ? 'CPU, JavaScript' : `GPU, ${glsl}`}).${noiseNote(rows)}`;
    dom.setAdvice({
      label: chosen.label,
      sceneLabel: `${scene.label.toLowerCase()}, ${src.measured ? words.short : PRECISION_WORDS[rec.precision] ?? rec.precision}`,
      reasonText: `${rec.reason} ${words.sentence}${practicalNote(alt, rec, rows)}`,
      criterionText: `Criterion: ${CRITERION}. Budget: ${budget.label}. ${costNote} Domain: ${scene.note}`,
    });
    const problem = glslOf(values.errors) ? '' : gpuProblem; // shown until the GPU is chosen again
    dom.setSource(src.waiting
      ? `Measuring the errors on this GPU in ${src.waiting}… The chart shows the JavaScript emulation until the read-back is done.`
      : problem, !src.waiting && Boolean(problem));
    gpuNote.textContent = mediumpNote(gpuPrecisionProbe());
    gpuNote.hidden = !gpuNote.textContent;
    dom.setTable(rows, {
      costHeader: mode === 'static' ? 'Cost (static count)' : `Cost (${mode === 'cpu' ? 'CPU' : 'GPU'} ns/eval)`,
      captionText: `${scene.label}: every method, cheapest first (errors: ${words.short})`,
      budgetCodes: budget.codes,
    });
    dom.setDevice(deviceText());
    view = { scene, budget, rec, rows, mode, chosen, source: src.source, glsl: src.glsl, words };
  }

  function deviceText() {
    if (!results) return 'No benchmark run yet on this device: the costs are static instruction counts.';
    const f = results.frames;
    const frames = f ? ` Frame at ${f.width}×${f.height}: hero spheres ${formatNs(f.spheres.msPerFrame).replace(' ns', ' ms')}, `
      + `three.js MeshPhysicalMaterial ${formatNs(f.threePhysical.msPerFrame).replace(' ns', ' ms')} (the hero costs ×${f.ratio.toFixed(2)}).` : '';
    const failed = results.device.gpuError ? ` GPU timing failed: ${results.device.gpuError}` : '';
    return `Measured ${results.date ? new Date(results.date).toLocaleString() : ''} on ${results.device.renderer ?? 'no WebGL2 (CPU only)'}; `
      + `timer: ${results.device.timer ?? '–'}.${frames}${failed}`;
  }

  async function run(size) {
    if (running) return running;
    controller = new AbortController();
    dom.setRunning(true);
    const started = performance.now();
    running = runBenchmark(dom.stage, {
      size, signal: controller.signal, whenVisible: gate.whenVisible, onProgress: (fraction, label) => dom.setProgress(fraction, label),
    }).then((next) => {
      results = next;
      saveCachedResults(next);
      dom.setStatus(`Done in ${((performance.now() - started) / 1000).toFixed(1)} s`);
      ctx.invalidate(); // redraws (update) and refreshes the description
      return next;
    }, (error) => {
      dom.setStatus(error?.name === 'AbortError' ? 'Cancelled' : `Benchmark failed: ${error?.message ?? error}`);
      if (error?.name !== 'AbortError') console.warn(error);
      throw error;
    }).finally(() => {
      dom.setRunning(false);
      running = null;
      controller = null;
    });
    return running;
  }

  update();
  const auto = new URLSearchParams(window.location.search).get('bench');
  const autorun = auto && Object.hasOwn(BENCH_SIZES, auto) ? run(auto).catch(() => null) : null;

  return {
    chart,
    get results() { return results; },
    get view() { return view; },
    /** The auto-run started by ?bench=…, or null. */
    autorun,
    /** The GPU read-back under way ("Error measured by" this GPU), or null. */
    get gpuMeasurement() { return measuring?.promise ?? null; },
    run,
    update,
    describe() {
      const { scene, budget, chosen, rows, mode, words, glsl } = view;
      const worst = rows.filter((r) => r.methodId !== chosen.methodId).sort((a, b) => b.maxCodes - a.maxCodes)[0];
      const full = glsl === 'mediump' && gpuPrecisionProbe()?.probe.mediumpIsFullPrecision
        ? ' mediump runs at full precision on this GPU, so these are float32 errors.' : '';
      return `For ${scene.label.toLowerCase()} ${words.phrase}, with a budget of ${budget.codes} `
        + `8-bit codes at the worst pixel, the recommendation is ${chosen.label}: worst error ${formatCodes(chosen.maxCodes)} codes, `
        + `cost ${chosen.costText}${mode === 'static' ? ' (static count)' : ''}. `
        + `${rows.filter((r) => r.passes).length} of ${rows.length} methods are within the budget; `
        + `the worst is ${worst?.label ?? '–'} at ${formatCodes(worst?.maxCodes)} codes.${full}`;
    },
    csv() {
      const { rows, scene, mode, source } = view;
      return {
        filename: `speed-accuracy-${scene.id}-${source}.csv`,
        columns: {
          method: rows.map((r) => r.methodId),
          error_source: rows.map(() => (source === 'js' ? `js-${scene.precision}` : source)),
          [`cost_${mode}`]: rows.map((r) => r.x ?? NaN),
          cost_min: rows.map((r) => r.xMin ?? NaN),
          cost_max: rows.map((r) => r.xMax ?? NaN),
          worst_codes: rows.map((r) => r.maxCodes),
          mean_codes: rows.map((r) => r.meanCodes),
          max_abs_error: rows.map((r) => r.max),
          theta_at_max_deg: rows.map((r) => (r.thetaAtMax === null ? NaN : toDegrees(r.thetaAtMax))),
          within_budget: rows.map((r) => (r.passes ? 1 : 0)),
          on_front: rows.map((r) => (r.onFront ? 1 : 0)),
        },
      };
    },
    /** The full results (the last run, or errors only) as benchCsv columns. */
    resultsCsv: () => benchCsv(currentResults()),
    resultsJson: () => currentResults(),
    resultsTable: () => benchTable(currentResults()),
    png: () => chart.toDataURL(),
    dispose() {
      disposed = true;
      controller?.abort(new DOMException('Panel closed', 'AbortError'));
      gate.dispose();
      chart.dispose();
    },
  };
}
