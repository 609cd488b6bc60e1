// @ts-check
// What the speed-accuracy panel shows for its values: every method of the scene as a row (cost,
// worst and mean display error, the Pareto front, the budget's verdict), the advisor's pick with
// its reason, the chart's data and the lines of words around it, the description and the CSV.
// Pure: the runs (runs.js) supply the benchmark's results and the GPU's read-back errors. Its
// words are the catalogue's ("speed-accuracy"), each sentence one message.
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';
import { timerName } from '../../gl/timeMethodsGpu.js';
import { gpuPrecisionFor, measuredCosts } from '../../methods/benchResults.js';
import { criterionText, displayBudget, recommendWithin } from '../../methods/displayBudgets.js';
import { recommendWithErrors } from '../../methods/gpuErrors.js';
import { methodById } from '../../methods/methods.js';
import { paretoFront } from '../../methods/paretoFront.js';
import { sceneById } from '../../methods/scenes.js';
import { toDegrees } from '../../optics/angles.js';
import { angle, fixed, tickLabel } from '../../ui/format.js';
import { pageLocale } from '../../ui/safeLocale.js';
import { mediumpNote, precisionWords, sourceWords } from './errorSources.js';
import { glslOf } from './glslOf.js';
import { formatCodes, formatNs, shortDecimal } from './formatMeasures.js';
import { readBackProblem } from './readBackProblem.js';

const t = messages('speed-accuracy', english);
const METHOD_MARK = '\u0001'; // where the method's name goes in the pick's sentence

/** @typedef {import('../../methods/benchResults.js').BenchResults} BenchResults */
/** @typedef {ReturnType<typeof recommendWithin>} Recommendation */
/** @typedef {ReturnType<typeof speedAccuracyView>} SpeedAccuracyView */
/**
 * A method's row: its error and cost as recommend() tables them, its cost as plotted (x, with the spread when measured:
 * absent for a cost not measured) and in words, the case of its largest error, whether it is the pick and on the front.
 * @typedef {import('../../methods/advisor.js').Row & { x?: number, xMin?: number, xMax?: number, text?: string,
 *   costText: string, caseText: string, recommended: boolean, onFront: boolean }} ViewRow
 */

/** A number as short as it is (1.3725, 0.5, 12.75), with the page's decimal separator. */
const plain = (/** @type {number} */ v) => tickLabel(v, 1e-6);

/**
 * The case of a scene where a method's error is largest: its indices, or its metal's n and k.
 * @param {string} kind
 * @param {readonly number[] | null} args
 */
function caseText(kind, args) {
  if (!args) return '';
  return kind === 'dielectric' ? `n ${plain(args[0])} → ${shortDecimal(args[1])}` : `n ${plain(args[0])}, k ${plain(args[1])}`;
}

/**
 * The cheaper pick under the "acceptable" budget (5 % of the range, a round figure just above the
 * worst error on plastics of the Schlick that Filament, Godot, three.js and UE4 ship; see
 * displayBudgets.js), when it differs from the strict one, with its measured cost in error.
 * @param {Recommendation | null} alt
 * @param {Recommendation} rec
 * @param {ViewRow[]} rows
 */
function practicalNote(alt, rec, rows) {
  if (!alt?.invisible || alt.methodId === rec.methodId) return '';
  const row = rows.find((r) => r.methodId === alt.methodId);
  if (!row) return ''; // a pick is always one of the rows
  const args = { method: row.label, worst: formatCodes(row.maxCodes), mean: formatCodes(row.meanCodes) };
  // The worst codes need not lie where |ΔR| is largest (sRGB is steeper for dark values): that angle is said apart.
  if (row.thetaAtMax === null) return ` ${t('practicalNoAngle', args)}`;
  return ` ${t('practical', { ...args, angle: angle(toDegrees(row.thetaAtMax), 1) })}`;
}

/**
 * A warning when timings overlap so much that their order is not to be trusted.
 * @param {ViewRow[]} rows
 */
function noiseNote(rows) {
  const noisy = rows.filter((r) => r.xMin !== undefined && r.xMax !== undefined && r.x !== undefined && Number.isFinite(r.xMin)
    && (r.xMax - r.xMin > Math.abs(r.x) || r.x <= 0));
  return noisy.length ? ` ${t('noisy', { count: noisy.length, noisy: String(noisy.length), all: String(rows.length) })}` : '';
}

/**
 * A method's cost: the static count, or the measured median with its spread (null when it was not measured).
 * @param {BenchResults | null} results
 * @param {import('../../methods/methods.js').Method} method
 * @param {string} glsl
 * @param {string} mode  'static', 'cpu' or 'gpu'
 * @returns {{ x: number, xMin?: number, xMax?: number, text: string } | null}
 */
function costOf(results, method, glsl, mode) {
  if (mode === 'static' || !results) return { x: method.cost.static, text: `${method.cost.static}` };
  const row = results.methods.find((m) => m.id === method.id);
  const spread = mode === 'cpu' ? row?.cpu?.nsPerEval : glsl === 'mediump' ? row?.gpu?.mediump?.nsPerEval : row?.gpu?.nsPerEval;
  if (!spread || !Number.isFinite(spread.median)) return null;
  return { x: spread.median, xMin: spread.min, xMax: spread.max, text: formatNs(spread) };
}

/**
 * The device line under the benchmark bar.
 * @param {BenchResults | null} results
 */
export function deviceText(results) {
  if (!results) return t('noRunYet');
  const f = results.frames;
  const sentences = [t('measuredOn', {
    when: results.date ? new Date(results.date).toLocaleString(pageLocale()) : '',
    device: results.device.renderer ?? t('noWebgl2Device'),
    timer: results.device.timer ? timerName(results.device.timer) : '–',
  })];
  if (f?.spheresView) {
    const ms = (/** @type {import('../../methods/benchResults.js').FramePart | undefined} */ side) => formatNs(side?.msPerFrame, 'ms');
    sentences.push(t('frameCostParts', {
      width: String(f.width), height: String(f.height), hero: ms(f.spheres), view: ms(f.spheresView), onePass: ms(f.spheresOnePass),
      peer: ms(f.threePhysical), plain: ms(f.threePlain), ratio: fixed(f.ratio, 2), plainRatio: fixed(f.plainRatio ?? NaN, 2),
      copy: ms(f.copy),
    }));
  } else if (f) { // results kept from before the frame was measured in parts
    sentences.push(t('frameCost', {
      width: String(f.width), height: String(f.height), hero: formatNs(f.spheres.msPerFrame, 'ms'),
      peer: formatNs(f.threePhysical.msPerFrame, 'ms'), ratio: fixed(f.ratio, 2),
    }));
  }
  const precisionCost = mediumpCostRatio(results);
  if (precisionCost !== null) {
    const verdict = precisionCost > 1.05 ? 'mediumpSlower' : precisionCost < 0.95 ? 'mediumpFaster' : 'mediumpSame';
    sentences.push(t(verdict, { ratio: fixed(precisionCost, 2) }));
  }
  if (results.device.gpuError) sentences.push(t('gpuTimingFailed', { error: results.device.gpuError }));
  return sentences.join(' ');
}

/**
 * What mediump costs against highp on this GPU, as measured: all the methods' median times in
 * mediump over all of them in highp (a sum, so that one method's timing noise near zero does not
 * swing it), or null without both or when highp's sum is not above zero. Whether mediump is cheaper
 * is the GPU's to say: on an NVIDIA H200 it was slower for every method.
 * @param {BenchResults | null} results
 */
export function mediumpCostRatio(results) {
  let highp = 0;
  let mediump = 0;
  for (const row of results?.methods ?? []) {
    const h = row.gpu?.nsPerEval?.median;
    const m = row.gpu?.mediump?.nsPerEval?.median;
    if (h === undefined || m === undefined || !Number.isFinite(h) || !Number.isFinite(m)) return null;
    highp += h;
    mediump += m;
  }
  return highp > 0 ? mediump / highp : null;
}

/**
 * The status line after a benchmark (runs.js BenchmarkEnd): how long it took, that it was
 * cancelled, or why it failed.
 * @param {import('./runs.js').BenchmarkEnd} end
 */
export function statusText(end) {
  if ('done' in end) return t('doneIn', { seconds: fixed(end.done / 1000, 1) });
  if ('cancelled' in end) return t('cancelled');
  const { failed } = end;
  return t('benchmarkFailed', { error: String(failed instanceof Error ? failed.message : failed) });
}

/**
 * Everything the panel draws for its values, from what the runs hold (runs.js SpeedAccuracyState).
 * source: { source, glsl, measured, waiting } (the errors to plot: the GPU's read-back, or null for
 * the JS emulation; waiting: the precision being read back); results: the benchmark's, or null;
 * readBackError: why the GPU read-back failed (null if it did not); probe: what mediump is on this
 * GPU, once measured (or null).
 * @param {import('../../host/panelContract.js').ValuesOf<typeof import('./schema.js').schema>} values
 * @param {import('./runs.js').SpeedAccuracyState} state
 */
export function speedAccuracyView(values, { source: src, results, readBackError, probe }) {
  const problem = readBackError ? readBackProblem(readBackError) : '';
  const scene = sceneById(values.scene);
  const budget = displayBudget(values.budget);
  const glsl = src.glsl ?? gpuPrecisionFor(scene.precision); // GPU timings in the read-back's precision
  const wanted = values.cost;
  const costs = wanted === 'static' ? {} : measuredCosts(results, scene, wanted, glsl);
  const mode = Object.keys(costs).length > 0 ? wanted : 'static';
  const words = sourceWords(src.source, scene, src.measured?.device?.renderer);
  const { measured, glsl: measuredIn } = src;
  /** @type {(b: ReturnType<typeof displayBudget>) => Recommendation} */
  const recommendFor = (b) => (measured && measuredIn
    ? {
      ...recommendWithErrors(scene, measured.errors, costs, {
        budgetCodes: b.codes, where: t('gpuWhere', { scene: scene.label, precision: measuredIn }), precision: measuredIn,
      }),
      budget: b,
      criterion: criterionText(),
    }
    : recommendWithin(scene, costs, b.id));
  const rec = recommendFor(budget);
  // Under a stricter budget, say what the "acceptable" judgement (what engines ship) would pick.
  const lenient = displayBudget('acceptable');
  const alt = budget.codes < lenient.codes ? recommendFor(lenient) : null;
  /** @type {ViewRow[]} */
  const rows = rec.table.map((r) => {
    const method = methodById(r.methodId);
    const cost = costOf(results, method, glsl, mode); // measured for every method, or none (then mode is 'static')
    return {
      ...r, ...cost, costText: cost ? cost.text : '–',
      caseText: caseText(scene.kind, r.caseAtMax), recommended: r.methodId === rec.methodId, onFront: false,
    };
  });
  const points = rows.map((r) => ({
    id: r.methodId, name: methodById(r.methodId).short, x: r.x, xMin: r.xMin, xMax: r.xMax, y: r.maxCodes,
    nan: !Number.isFinite(r.maxCodes), passes: r.passes, recommended: r.recommended,
  }));
  const front = paretoFront(points.map((p) => ({ x: p.x, y: p.nan ? Infinity : p.y })));
  rows.forEach((r, i) => { r.onFront = front.includes(i); });
  const chosen = rows.find((r) => r.recommended);
  if (!chosen) throw new Error(`the pick ${rec.methodId} is not among the rows`); // recommend() picks from its table
  const costNote = mode === 'static'
    ? t(wanted === 'static' ? 'costsStatic' : 'costsStaticUntilRun')
    : `${mode === 'cpu' ? t('costsMeasuredCpu') : t('costsMeasuredGpu', { precision: glsl })}${noiseNote(rows)}`;
  const shownProblem = glslOf(values.errors) ? '' : problem; // said until the GPU is chosen again
  // The pick's sentence with the method in its own element: split where the method goes, so a
  // language may put it anywhere in the sentence.
  const pickSource = src.measured ? words.short : precisionWords(rec.precision);
  const pick = t('recommendedFor', { scene: scene.inText, source: pickSource, method: METHOD_MARK });
  const [pickBefore, pickAfter = ''] = pick.split(METHOD_MARK);
  return {
    scene, budget, rec, rows, mode, chosen, source: src.source, glsl: src.glsl, words,
    chart: {
      points, front, budget: { codes: budget.codes, label: t('budgetLine', { count: budget.codes, codes: plain(budget.codes) }) },
      xLabel: mode === 'static' ? t('xStatic') : mode === 'cpu' ? t('xCpu') : t('xGpu', { precision: glsl }),
      yLabel: t('yLabel'),
      title: t('chartTitle', { scene: scene.label, source: words.short }),
      words: { front: t('paretoFront'), nan: t('nanAxis') },
    },
    advice: {
      label: chosen.label,
      pickBefore,
      pickAfter,
      reasonText: `${rec.reason} ${words.sentence}${practicalNote(alt, rec, rows)}`,
      criterionText: t('criterionLine', { criterion: criterionText(), budget: budget.label, costs: costNote, domain: scene.note }),
    },
    /** The line about the error source: the read-back under way, or why it failed (a warning). */
    sourceLine: src.waiting
      ? { text: t('measuring', { precision: src.waiting }), warning: false }
      : { text: shownProblem, warning: Boolean(shownProblem) },
    gpuNote: mediumpNote(probe),
    table: {
      costHeader: mode === 'static' ? t('costStaticHeader') : mode === 'cpu' ? t('costCpuHeader') : t('costGpuHeader'),
      captionText: t('caption', { scene: scene.label, source: words.short }),
      budgetCodes: budget.codes,
    },
    device: deviceText(results),
  };
}

/**
 * The key numbers in words (the panel's description); probe: what mediump is on this GPU, once measured (or null).
 * @param {SpeedAccuracyView} view
 * @param {import('./runs.js').GpuProbe | null} probe
 */
export function describeView(view, probe) {
  const { scene, budget, chosen, rows, mode, words, glsl } = view;
  const worst = rows.filter((r) => r.methodId !== chosen.methodId).sort((a, b) => b.maxCodes - a.maxCodes).at(0);
  const text = t('describe', {
    scene: scene.inText, phrase: words.phrase, count: budget.codes, codes: plain(budget.codes), method: chosen.label,
    worst: formatCodes(chosen.maxCodes), cost: chosen.costText, static: mode === 'static' ? 'yes' : 'no',
    passing: String(rows.filter((r) => r.passes).length), all: String(rows.length),
    worstMethod: worst?.label ?? '–', worstCodes: worst ? formatCodes(worst.maxCodes) : '–',
  });
  const full = glsl === 'mediump' && probe?.probe.mediumpIsFullPrecision;
  return full ? `${text} ${t('describeFullMediump')}` : text;
}

/**
 * The plotted rows as CSV columns.
 * @param {SpeedAccuracyView} view
 */
export function viewCsv(view) {
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
}
