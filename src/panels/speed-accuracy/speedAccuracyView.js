// @ts-check
// What the speed-accuracy panel shows for its values: every method of the scene as a row (cost,
// worst and mean display error, the Pareto front, the budget's verdict), the advisor's pick with
// its reason, the chart's data and the lines of words around it, the description and the CSV.
// Pure: the model (model.js) supplies the benchmark's results and the GPU's read-back errors.
import { gpuPrecisionFor, measuredCosts } from '../../methods/benchResults.js';
import { criterionText, displayBudget, recommendWithin } from '../../methods/displayBudgets.js';
import { recommendWithErrors } from '../../methods/gpuErrors.js';
import { methodById } from '../../methods/methods.js';
import { paretoFront } from '../../methods/paretoFront.js';
import { sceneById } from '../../methods/scenes.js';
import { toDegrees } from '../../optics/angles.js';
import { angle, fixed } from '../../ui/format.js';
import { pageLocale } from '../../ui/safeLocale.js';
import {
  glslOf, mediumpNote, PRECISION_WORDS, sourceWords,
} from './errorSources.js';
import { formatCodes, formatNs, shortDecimal } from './formatMeasures.js';

function caseText(kind, args) {
  if (!args) return '';
  return kind === 'dielectric' ? `n ${args[0]} → ${shortDecimal(args[1])}` : `n ${args[0]}, k ${args[1]}`;
}

/**
 * The cheaper pick under the "acceptable" budget (5 % of the range, the judgement behind the
 * Schlick that Filament, Godot, three.js and UE4 ship; see displayBudgets.js), when it differs
 * from the strict one, with its measured cost in error.
 */
function practicalNote(alt, rec, rows) {
  if (!alt?.invisible || alt.methodId === rec.methodId) return '';
  const row = rows.find((r) => r.methodId === alt.methodId);
  // The worst codes need not lie where |ΔR| is largest (sRGB is steeper for dark values): that angle is said apart.
  const where = row.thetaAtMax === null ? '' : ` (its largest |ΔR| at ${angle(toDegrees(row.thetaAtMax), 1)})`;
  return ' If an error of up to 5 % of the display range is acceptable (the judgement behind the Schlick that engines ship), '
    + `${row.label} would do: ${formatCodes(row.maxCodes)} codes at worst, ${formatCodes(row.meanCodes)} on average${where}.`;
}

/** A warning when timings overlap so much that their order is not to be trusted. */
function noiseNote(rows) {
  const noisy = rows.filter((r) => Number.isFinite(r.xMin) && (r.xMax - r.xMin > Math.abs(r.x) || r.x <= 0));
  return noisy.length ? ` ${noisy.length} of ${rows.length} timings vary by more than their median (or are ≤ 0): `
    + 'the machine was busy, so the order of close methods is uncertain; run again when it is idle.' : '';
}

/** A method's cost: the static count, or the measured median with its spread (null when it was not measured). */
function costOf(results, method, glsl, mode) {
  if (mode === 'static' || !results) return { x: method.cost.static, text: `${method.cost.static}` };
  const row = results.methods.find((m) => m.id === method.id);
  const spread = mode === 'cpu' ? row?.cpu?.nsPerEval : glsl === 'mediump' ? row?.gpu?.mediump?.nsPerEval : row?.gpu?.nsPerEval;
  if (!spread || !Number.isFinite(spread.median)) return null;
  return { x: spread.median, xMin: spread.min, xMax: spread.max, text: formatNs(spread) };
}

/** The device line under the benchmark bar. */
export function deviceText(results) {
  if (!results) return 'No benchmark run yet on this device: the costs are static instruction counts.';
  const f = results.frames;
  const ms = (spread) => formatNs(spread).replace(' ns', ' ms');
  const frames = f ? ` Frame at ${f.width}×${f.height}: hero spheres ${ms(f.spheres.msPerFrame)}, `
    + `three.js MeshPhysicalMaterial ${ms(f.threePhysical.msPerFrame)} (the hero costs ×${fixed(f.ratio, 2)}).` : '';
  const failed = results.device.gpuError ? ` GPU timing failed: ${results.device.gpuError}` : '';
  const when = results.date ? new Date(results.date).toLocaleString(pageLocale()) : '';
  return `Measured ${when} on ${results.device.renderer ?? 'no WebGL2 (CPU only)'}; `
    + `timer: ${results.device.timer ?? '–'}.${frames}${failed}`;
}

/**
 * Everything the panel draws for its values. source: { source, glsl, measured, waiting } from the
 * model (the errors to plot: the GPU's read-back, or null for the JS emulation; waiting: the
 * precision being read back); results: the benchmark's, or null; problem: why the GPU read-back
 * failed ('' if it did not); probe: what mediump is on this GPU, once measured (or null).
 */
export function speedAccuracyView(values, { source: src, results, problem, probe }) {
  const scene = sceneById(values.scene);
  const budget = displayBudget(values.budget);
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
      criterion: criterionText(),
    }
    : recommendWithin(scene, costs, b.id));
  const rec = recommendFor(budget);
  // Under a stricter budget, say what the "acceptable" judgement (what engines ship) would pick.
  const lenient = displayBudget('acceptable');
  const alt = budget.codes < lenient.codes ? recommendFor(lenient) : null;
  const rows = rec.table.map((r) => {
    const method = methodById(r.methodId);
    const cost = costOf(results, method, glsl, mode);
    return {
      ...r, ...cost, costText: cost.text,
      caseText: caseText(scene.kind, r.caseAtMax), recommended: r.methodId === rec.methodId, onFront: false,
    };
  });
  const points = rows.map((r) => ({
    id: r.methodId, name: methodById(r.methodId).short, x: r.x, xMin: r.xMin, xMax: r.xMax, y: r.maxCodes,
    nan: !Number.isFinite(r.maxCodes), passes: r.passes, recommended: r.recommended,
  }));
  const front = paretoFront(points.map((p) => ({ x: p.x, y: p.nan ? Infinity : p.y })));
  rows.forEach((r, i) => { r.onFront = front.includes(i); });
  const unit = mode === 'static' ? 'static instruction count (SPIR-V)'
    : mode === 'cpu' ? 'CPU ns per evaluation (JS, float64; median, min–max)'
      : `GPU ns per evaluation, ${glsl} (median, min–max)`;
  const chosen = rows.find((r) => r.recommended);
  const costNote = mode === 'static'
    ? (wanted === 'static' ? 'Costs: static instruction counts.' : 'Costs: static instruction counts until you run the benchmark.')
    : `Costs: measured here (${mode === 'cpu' ? 'CPU, JavaScript' : `GPU, ${glsl}`}).${noiseNote(rows)}`;
  const shownProblem = glslOf(values.errors) ? '' : problem; // said until the GPU is chosen again
  return {
    scene, budget, rec, rows, mode, chosen, source: src.source, glsl: src.glsl, words,
    chart: {
      points, front, budget: { codes: budget.codes, label: `${budget.codes} codes` },
      xLabel: `Cost: ${unit}`, yLabel: 'Worst display error, 8-bit codes (log)',
      title: `${scene.label}, ${words.short}`,
    },
    advice: {
      label: chosen.label,
      sceneLabel: `${scene.label.toLowerCase()}, ${src.measured ? words.short : PRECISION_WORDS[rec.precision] ?? rec.precision}`,
      reasonText: `${rec.reason} ${words.sentence}${practicalNote(alt, rec, rows)}`,
      criterionText: `Criterion: ${criterionText()}. Budget: ${budget.label}. ${costNote} Domain: ${scene.note}`,
    },
    /** The line about the error source: the read-back under way, or why it failed (a warning). */
    sourceLine: src.waiting
      ? {
        text: `Measuring the errors on this GPU in ${src.waiting}… The chart shows the JavaScript emulation until the read-back is done.`,
        warning: false,
      }
      : { text: shownProblem, warning: Boolean(shownProblem) },
    gpuNote: mediumpNote(probe),
    table: {
      costHeader: mode === 'static' ? 'Cost (static count)' : `Cost (${mode === 'cpu' ? 'CPU' : 'GPU'} ns/eval)`,
      captionText: `${scene.label}: every method, cheapest first (errors: ${words.short})`,
      budgetCodes: budget.codes,
    },
    device: deviceText(results),
  };
}

/** The key numbers in words (the panel's description); probe: what mediump is on this GPU, once measured (or null). */
export function describeView(view, probe) {
  const { scene, budget, chosen, rows, mode, words, glsl } = view;
  const worst = rows.filter((r) => r.methodId !== chosen.methodId).sort((a, b) => b.maxCodes - a.maxCodes)[0];
  const full = glsl === 'mediump' && probe?.probe.mediumpIsFullPrecision
    ? ' mediump runs at full precision on this GPU, so these are float32 errors.' : '';
  return `For ${scene.label.toLowerCase()} ${words.phrase}, with a budget of ${budget.codes} `
    + `8-bit codes at the worst pixel, the recommendation is ${chosen.label}: worst error ${formatCodes(chosen.maxCodes)} codes, `
    + `cost ${chosen.costText}${mode === 'static' ? ' (static count)' : ''}. `
    + `${rows.filter((r) => r.passes).length} of ${rows.length} methods are within the budget; `
    + `the worst is ${worst?.label ?? '–'} at ${formatCodes(worst?.maxCodes)} codes.${full}`;
}

/** The plotted rows as CSV columns. */
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
