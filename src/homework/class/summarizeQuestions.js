// @ts-check
// What the class got wrong, per question of the sheet, as plain data for a plot (bins, counts,
// labels): the share right; for a choice, how often each option was chosen and, for each wrong one,
// the misconception it stands for (the option's explanation, as the first student who chose it
// while it was wrong saw it: the explanations quote that student's numbers); for a number, a
// histogram of answer ÷ computed value on a log scale, where a slip by a factor shows as a peak at
// the same place for every student whatever their numbers (×2, ×½, degrees for radians, a
// percentage for a fraction), plus counts of the question's named slips (questionSlips.js); for a
// prediction, a histogram of the predicted minus the true angle. Only hand-ins that count are used.
import { questionById } from '../questions.js';
import { questionSlips } from './questionSlips.js';

const RATIO_STEP = 0.05; // a twentieth of a decade (×1.12): a rounded answer stays in its factor's bin
const RATIO_DECADES = 3; // ×0.001 to ×1000
const OFFSET_STEP = 5; // degrees
// What a slip by each factor means depends on the answer's unit: ×100 is a percentage typed for a
// fraction, not for an angle; ×57.3 is degrees for radians only where the answer is an angle.
const FACTORS = [
  { factor: 2, text: '×2' }, { factor: 0.5, text: '×½' },
  { factor: 10, text: '×10: a decimal place' }, { factor: 0.1, text: '÷10: a decimal place' },
  { factor: 100, text: '×100', meaning: { fraction: 'a percentage for a fraction' } }, { factor: 0.01, text: '÷100' },
  { factor: 180 / Math.PI, text: '×57.3', meaning: { deg: 'degrees for radians' } },
  { factor: Math.PI / 180, text: '÷57.3', meaning: { deg: 'radians for degrees' } },
];

/**
 * @typedef {{ lo: number, hi: number, count: number }} Bin
 * @typedef {{ id: string, text: string, chosen: number, chosenWhenRight: number, chosenWhenWrong: number, rightFor: number,
 *   why: string | null }} OptionCount
 * @typedef {{ item: number, question: string, kind: string, unit: string | null, tolerance: number | null, students: number,
 *   right: number, wrong: number, unanswered: number, shareRight: number | null,
 *   options?: OptionCount[],
 *   ratio?: { step: number, bins: Bin[], labels: { at: number, factor: number, text: string, count: number }[],
 *     below: number, above: number, opposite: number, flipped: number, zero: number, noRatio: number },
 *   slips?: { label: string, count: number }[],
 *   offset?: { step: number, bins: Bin[] } }} QuestionSummary
 */

/** Bins of width `step` centred on multiples of it, from −half·step… to …+half·step. */
function centredBins(half, step) {
  return Array.from({ length: 2 * half + 1 }, (_, i) => ({ lo: (i - half - 0.5) * step, hi: (i - half + 0.5) * step, count: 0 }));
}

function addTo(bins, x, step) {
  const half = (bins.length - 1) / 2;
  const i = Math.round(x / step) + half;
  if (i < 0) return -1;
  if (i >= bins.length) return 1;
  bins[i].count += 1;
  return 0;
}

function choiceSummary(question, entries) {
  const params = entries[0]?.result.params;
  if (!params) return [];
  return question.options(params).map((option) => {
    const count = { id: option.id, text: option.text(params), chosen: 0, chosenWhenRight: 0, chosenWhenWrong: 0, rightFor: 0, why: null };
    for (const { result: r } of entries) {
      if (r.expected === option.id) count.rightFor += 1;
      if (r.answer !== option.id) continue;
      count.chosen += 1;
      if (r.correct) count.chosenWhenRight += 1;
      else {
        count.chosenWhenWrong += 1;
        count.why ??= r.explanation; // the option's why(params), for this student's numbers
      }
    }
    return count;
  });
}

function numericSummary(question, entries) {
  const half = RATIO_DECADES / RATIO_STEP;
  const ratio = {
    step: RATIO_STEP, bins: centredBins(half, RATIO_STEP), labels: [], below: 0, above: 0, opposite: 0, flipped: 0, zero: 0, noRatio: 0,
  };
  const logs = [];
  const slipCounts = new Map();
  for (const { result: r } of entries) {
    if (!r.answered) continue;
    if (r.expected === 0) {
      ratio.noRatio += 1;
      continue;
    }
    const q = r.value / r.expected;
    if (q === 0) ratio.zero += 1;
    else if (q < 0) {
      ratio.opposite += 1;
      if (Math.abs(Math.log10(-q)) <= RATIO_STEP / 2) ratio.flipped += 1;
    } else {
      const log = Math.log10(q);
      logs.push(log);
      const side = addTo(ratio.bins, log, RATIO_STEP);
      if (side < 0) ratio.below += 1;
      if (side > 0) ratio.above += 1;
    }
    if (r.correct) continue;
    for (const slip of questionSlips(question, r.params)) {
      // A slip that lands within the tolerance of the true value is no slip for this student.
      if (Math.abs(slip.value - r.expected) <= question.tolerance) continue;
      if (Math.abs(r.value - slip.value) <= Math.max(question.tolerance, 0.005 * Math.abs(slip.value))) {
        slipCounts.set(slip.label, (slipCounts.get(slip.label) ?? 0) + 1);
      }
    }
  }
  ratio.labels = FACTORS.map(({ factor, text: short, meaning }) => {
    const at = Math.log10(factor);
    const text = meaning?.[question.unit] ? `${short}: ${meaning[question.unit]}` : short;
    return { at, factor, text, count: logs.filter((x) => Math.abs(x - at) <= RATIO_STEP / 2).length };
  });
  // Every slip the question names, counted or not (a class with no hand-in has none to name).
  const slips = (entries.length ? questionSlips(question, entries[0].result.params) : [])
    .map(({ label }) => ({ label, count: slipCounts.get(label) ?? 0 }));
  for (const [label, count] of slipCounts) if (!slips.some((s) => s.label === label)) slips.push({ label, count });
  return { ratio, slips };
}

function predictSummary(entries) {
  const bins = centredBins(90 / OFFSET_STEP, OFFSET_STEP);
  for (const { result: r } of entries) if (r.answered) addTo(bins, r.answer - r.expected, OFFSET_STEP);
  return { step: OFFSET_STEP, bins };
}

/**
 * A summary per item of the sheet. grades: gradeClass's { ok: true, … }; gradebook: its
 * buildGradebook, whose counted rows are the students summarised (without it, every hand-in graded).
 * @param {{ sheet: any, graded: { source: string, result: any }[] }} grades
 * @param {{ rows: { key: number, counted: boolean }[] }} [gradebook]
 * @returns {QuestionSummary[]}
 */
export function summarizeQuestions(grades, gradebook) {
  const students = gradebook ? gradebook.rows.filter((row) => row.counted).map((row) => grades.graded[row.key]) : grades.graded;
  return grades.sheet.items.map((item, i) => {
    const question = /** @type {any} */ (questionById(item.question));
    const entries = students.map(({ source, result }) => ({ source, result: result.results[i] }));
    const right = entries.filter((e) => e.result.correct).length;
    const unanswered = entries.filter((e) => !e.result.answered).length;
    /** @type {QuestionSummary} */
    const summary = {
      item: i, question: question.id, kind: question.kind, unit: question.unit ?? null, tolerance: question.tolerance ?? null,
      students: entries.length, right, wrong: entries.length - right - unanswered, unanswered,
      shareRight: entries.length ? right / entries.length : null,
    };
    if (question.kind === 'choice') summary.options = choiceSummary(question, entries);
    else if (question.kind === 'numeric') Object.assign(summary, numericSummary(question, entries));
    else summary.offset = predictSummary(entries);
    return summary;
  });
}
