// @ts-check
// Panel `speed-accuracy`: every Fresnel method as a point, cost against worst display error, for a
// scene (domain and precision from scenes.js), with the Pareto front, the chosen budget as a line,
// and the advisor's pick (advisor.recommend via displayBudgets.recommendWithin) with its reason.
// Costs are the static SPIR-V instruction counts (computed; see methods.js) until "Run benchmark"
// measures them on this device (GPU ns per evaluation at the scene's precision, or CPU ns).
// Errors come from the JS emulation at the scene's precision, or ("Error measured by") from this
// GPU in highp or mediump: every sample rendered and read back (measureGpuErrors.js, gpuErrors.js).
// ?bench=normal|tiny runs the benchmark on load (npm run bench uses it). The view: the state and
// the runs are runs.js's, what is shown for them words.js's.
import { benchCsv, benchTable } from '../../methods/benchResults.js';
import { downloadText } from '../../host/exporters.js';
import { createVisibilityGate } from '../../ui/createVisibilityGate.js';
import { BENCH_SIZES, loadCachedResults, runBenchmark, saveCachedResults } from './runBenchmark.js';
import { createScatter } from './createScatter.js';
import { buildSpeedAccuracyDom } from './buildSpeedAccuracyDom.js';
import { cachedGpuErrors, gpuPrecisionProbe, measureGpuErrors } from './measureGpuErrors.js';
import { createSpeedAccuracyRuns } from './runs.js';
import {
  describeView, speedAccuracyView, statusText, viewCsv,
} from './words.js';
import './styles.css';
import { schema } from './schema.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

export { schema };

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const dom = buildSpeedAccuracyDom(root, {
    onRun: () => { runs.run('normal').catch(() => {}); },
    onCancel: () => runs.cancel(),
    onJson: () => downloadText(
      'fresnel-lab-speed-accuracy.json', `${JSON.stringify(runs.currentResults(), null, 2)}\n`, 'application/json',
    ),
  });
  // A run pauses between its steps while the panel is off screen, and says so.
  const gate = createVisibilityGate(root, {
    onPause: () => dom.setStatus(t('paused')),
  });
  const runs = createSpeedAccuracyRuns({
    values,
    readBack: { cached: cachedGpuErrors, measure: measureGpuErrors, probe: gpuPrecisionProbe },
    benchmark: (options) => runBenchmark(dom.stage, { ...options, whenVisible: gate.whenVisible }),
    storage: { load: loadCachedResults, save: saveCachedResults },
    hooks: {
      invalidate: () => ctx.invalidate(), // redraws (update) and refreshes the description
      useEmulation: () => ctx.set({ errors: 'js' }),
      running: (running) => dom.setRunning(running),
      progress: (fraction, label) => dom.setProgress(fraction, label),
      status: (end) => dom.setStatus(statusText(end)),
    },
  });
  const chart = createScatter(dom.chartHost, { ariaLabel: t('chartLabel') });
  const controllers = ctx.bind(ctx.gui.addFolder(t('folder')), ['scene', 'budget', 'errors', 'cost']);
  // Beside the "Error measured by" control: what mediump really is on this GPU, once measured.
  const gpuNote = document.createElement('p');
  gpuNote.className = 'sa-gui-note';
  gpuNote.setAttribute('role', 'status');
  controllers.errors.domElement.after(gpuNote);

  /** @type {import('./runs.js').SpeedAccuracyState} what the runs held at the last update */
  let state;
  /** @type {ReturnType<typeof speedAccuracyView>} what is shown for it */
  let view;
  function update() {
    state = runs.update();
    view = speedAccuracyView(values, state);
    chart.setData(view.chart);
    dom.setAdvice(view.advice);
    dom.setSource(view.sourceLine.text, view.sourceLine.warning);
    gpuNote.textContent = view.gpuNote;
    gpuNote.hidden = !gpuNote.textContent;
    dom.setTable(view.rows, view.table);
    dom.setDevice(view.device);
  }

  update();
  const auto = new URLSearchParams(window.location.search).get('bench');
  const autorun = auto && Object.hasOwn(BENCH_SIZES, auto) ? runs.run(auto).catch(() => null) : null;

  return {
    chart,
    runs,
    get results() { return runs.results; },
    get view() { return view; },
    /** The auto-run started by ?bench=…, or null. */
    autorun,
    /** The GPU read-back under way ("Error measured by" this GPU), or null. */
    get gpuMeasurement() { return runs.measurement; },
    run: runs.run,
    update,
    describe: () => describeView(view, state.probe),
    csv: () => viewCsv(view),
    /** The full results (the last run, or errors only) as benchCsv columns. */
    resultsCsv: () => benchCsv(runs.currentResults()),
    resultsJson: () => runs.currentResults(),
    resultsTable: () => benchTable(runs.currentResults()),
    png: () => chart.toDataURL(),
    dispose() {
      runs.dispose();
      gate.dispose();
      chart.dispose();
    },
  };
}
