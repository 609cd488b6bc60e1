// @ts-check
// What the class got wrong, per question of the sheet, as plain data for a plot (bins, counts,
// labels): the share right; for a choice, how often each option was chosen and, for each wrong one,
// the misconception it stands for (the option's explanation); for a number, a histogram of answer ÷
// computed value on a log scale, where a slip by a factor shows as a peak at the same place for
// every student whatever their numbers (×2, ×½, degrees converted twice, a percentage for a fraction),
// plus counts of the question's named slips (questionSlips.js); for a prediction, a histogram of the
// predicted minus the true angle. Only hand-ins that count are used.
//
// Numbers differ from student to student, so a card shows one student's instance of the question
// (`shown`: the first student counted): its prompt, its options and every explanation all come
// from those parameters, never one from one student and one from another.
//
// Every answer is counted once: in the histogram, in one bin (split into right and wrong, so a
// wrong answer a few per cent off is not hidden in the right answers' column) or outside it; and
// a wrong answer under at most one slip, the first that fits: a named slip (the closest), a factor,
// 0, the opposite sign, more than 1000× off.
import { knownQuestion } from '../questions.js';
import { trueOption } from '../gradeAnswer.js';
import { questionSlips } from './questionSlips.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const RATIO_STEP = 0.05; // a twentieth of a decade (×1.12): a rounded answer stays in its factor's bin
const RATIO_DECADES = 3; // ×0.001 to ×1000
const OFFSET_STEP = 5; // degrees
const t = messages('class', english);
// What a slip by each factor means depends on the answer's unit: ×100 is a percentage typed for a
// fraction, not for an angle; ×57.3 is degrees converted twice only where the answer is an angle.
// Each factor's label is the catalogue's factor.<name> (the short form a histogram's tick shows),
// and factor.<name>.<unit> (or .any) where it means a slip for answers in that unit.
/** @type {{ factor: number, name: string, meaning?: string[] }[]} */
const FACTORS = [
  { factor: 2, name: 'double' }, { factor: 0.5, name: 'half' },
  { factor: 10, name: 'times10', meaning: ['any'] }, { factor: 0.1, name: 'by10', meaning: ['any'] },
  { factor: 100, name: 'times100', meaning: ['fraction'] }, { factor: 0.01, name: 'by100' },
  { factor: 180 / Math.PI, name: 'toDegrees', meaning: ['deg'] },
  { factor: Math.PI / 180, name: 'toRadians', meaning: ['deg'] },
];

/**
 * A factor's label for answers in `unit`: with what the slip means where it means one for them.
 * @param {{ name: string, meaning?: string[] }} factor
 * @param {string | null} unit
 */
function factorText({ name, meaning = [] }, unit) {
  if (meaning.includes('any')) return t(`factor.${name}.any`);
  return unit !== null && meaning.includes(unit) ? t(`factor.${name}.${unit}`) : t(`factor.${name}`);
}

/**
 * @typedef {{ lo: number, hi: number, count: number, right: number, wrong: number }} Bin  count = right + wrong
 * @typedef {{ id: string, text: string, chosen: number, chosenWhenRight: number, chosenWhenWrong: number, rightFor: number,
 *   rightForShown: boolean, why: string | null }} OptionCount  text, why: for the shown instance's numbers (why: null where
 *   the option holds for them)
 * @typedef {{ item: number, question: string, unit: string | null, tolerance: number | null, students: number,
 *   right: number, wrong: number, unanswered: number, shareRight: number | null,
 *   shown: { params: unknown, sameForAll: boolean } | null }} SummaryBase
 * @typedef {{ step: number, bins: Bin[], labels: FactorLabel[],
 *   below: number, above: number, opposite: number, flipped: number, zero: number, noRatio: number }} Ratio
 * @typedef {SummaryBase & { kind: 'choice', options: OptionCount[] }} ChoiceSummary
 * @typedef {SummaryBase & { kind: 'numeric', ratio: Ratio, slips: { label: string, count: number }[],
 *   elsewhere: { zero: number, opposite: number, far: number } }} NumericSummary
 * @typedef {SummaryBase & { kind: 'predict', offset: { step: number, bins: Bin[] } }} PredictSummary
 * @typedef {ChoiceSummary | NumericSummary | PredictSummary} QuestionSummary
 *   ratio's below, above, opposite, zero, noRatio: answers (right or wrong) outside the histogram's bins;
 *   labels[].count, slips[].count, elsewhere: wrong answers, each under one of them at most
 * @typedef {{ at: number, factor: number, short: string, text: string, count: number }} FactorLabel
 * @typedef {import('../gradeHandIn.js').HandInResult} Result
 * @typedef {{ source: string, result: Result }} Entry  one student's answer to the question
 * @typedef {import('../questions.js').Question} Question
 * @typedef {import('../questions.js').ChoiceQuestion} ChoiceQuestion
 * @typedef {import('../questions.js').ValueQuestion} ValueQuestion
 */

/**
 * Bins of width `step` centred on multiples of it, from −half·step… to …+half·step.
 * @param {number} half
 * @param {number} step
 * @returns {Bin[]}
 */
function centredBins(half, step) {
  return Array.from({ length: 2 * half + 1 }, (_, i) => ({
    lo: (i - half - 0.5) * step, hi: (i - half + 0.5) * step, count: 0, right: 0, wrong: 0,
  }));
}

/**
 * Counts an answer in its bin, as right or wrong: 0, or −1 / 1 where it falls below / above every bin.
 * @param {Bin[]} bins
 * @param {number} x
 * @param {number} step
 * @param {boolean} correct
 */
function addTo(bins, x, step, correct) {
  const half = (bins.length - 1) / 2;
  const i = Math.round(x / step) + half;
  if (i < 0) return -1;
  if (i >= bins.length) return 1;
  bins[i].count += 1;
  if (correct) bins[i].right += 1;
  else bins[i].wrong += 1;
  return 0;
}

/**
 * @param {ChoiceQuestion} question
 * @param {Entry[]} entries
 * @param {unknown} params  the shown instance's (undefined where nobody is counted)
 * @returns {OptionCount[]}
 */
function choiceSummary(question, entries, params) {
  if (!params) return [];
  const holds = trueOption(question, params).id;
  return question.options(params).map((option) => {
    const rightForShown = option.id === holds;
    const count = {
      id: option.id, text: option.text(params), chosen: 0, chosenWhenRight: 0, chosenWhenWrong: 0, rightFor: 0, rightForShown,
      why: rightForShown ? null : option.why(params), // the misconception, in the shown instance's numbers
    };
    for (const { result: r } of entries) {
      if (r.expected === option.id) count.rightFor += 1;
      if (r.answer !== option.id) continue;
      count.chosen += 1;
      if (r.correct) count.chosenWhenRight += 1;
      else count.chosenWhenWrong += 1;
    }
    return count;
  });
}

/**
 * The named slip a wrong answer fits (the closest of those that fit), or null.
 * @param {ValueQuestion} question
 * @param {Result & { value: number, expected: number }} r
 */
function namedSlip(question, r) {
  /** @type {{ label: string, off: number } | null} */
  let best = null;
  for (const slip of questionSlips(question, r.params)) {
    // A slip that lands within the tolerance of the true value is no slip for this student.
    if (Math.abs(slip.value - r.expected) <= question.tolerance) continue;
    const off = Math.abs(r.value - slip.value);
    if (off <= Math.max(question.tolerance, 0.005 * Math.abs(slip.value)) && (!best || off < best.off)) best = { label: slip.label, off };
  }
  return best?.label ?? null;
}

/**
 * @param {ValueQuestion} question
 * @param {Entry[]} entries
 * @param {unknown} params  the shown instance's (undefined where nobody is counted)
 */
function numericSummary(question, entries, params) {
  const half = RATIO_DECADES / RATIO_STEP;
  /** @type {Ratio} */
  const ratio = {
    step: RATIO_STEP, bins: centredBins(half, RATIO_STEP), labels: [], below: 0, above: 0, opposite: 0, flipped: 0, zero: 0, noRatio: 0,
  };
  const factors = FACTORS.map((entry) => ({
    at: Math.log10(entry.factor), factor: entry.factor, short: t(`factor.${entry.name}`), text: factorText(entry, question.unit), count: 0,
  }));
  const elsewhere = { zero: 0, opposite: 0, far: 0 };
  /** @type {Map<string, number>} */
  const slipCounts = new Map();
  for (const { result } of entries) {
    // An answered value question's grade has the value read (gradeAnswer.js); expected is its number.
    const { value } = result;
    if (!result.answered || value === undefined || typeof result.expected !== 'number') continue;
    const r = { ...result, value, expected: result.expected };
    // The histogram: each answer in one bin, or outside them.
    const q = r.expected === 0 ? NaN : r.value / r.expected;
    const log = q > 0 ? Math.log10(q) : NaN;
    let side = 0;
    if (r.expected === 0) ratio.noRatio += 1;
    else if (q === 0) ratio.zero += 1;
    else if (q < 0) {
      ratio.opposite += 1;
      if (Math.abs(Math.log10(-q)) <= RATIO_STEP / 2) ratio.flipped += 1;
    } else {
      side = addTo(ratio.bins, log, RATIO_STEP, r.correct);
      if (side < 0) ratio.below += 1;
      if (side > 0) ratio.above += 1;
    }
    if (r.correct) continue;
    // The slips: each wrong answer under the first that fits, if any.
    const slip = namedSlip(question, r);
    const factor = Number.isFinite(log) ? factors.find((f) => Math.abs(log - f.at) <= RATIO_STEP / 2) : undefined;
    if (slip) slipCounts.set(slip, (slipCounts.get(slip) ?? 0) + 1);
    else if (factor) factor.count += 1;
    else if (q === 0) elsewhere.zero += 1;
    else if (q < 0) elsewhere.opposite += 1;
    else if (side !== 0) elsewhere.far += 1;
  }
  ratio.labels = factors;
  // Every slip the question names, counted or not (a class with no hand-in has none to name).
  const slips = (params ? questionSlips(question, params) : []).map(({ label }) => ({ label, count: slipCounts.get(label) ?? 0 }));
  for (const [label, count] of slipCounts) if (!slips.some((s) => s.label === label)) slips.push({ label, count });
  return { ratio, slips, elsewhere };
}

/** @param {Entry[]} entries */
function predictSummary(entries) {
  const bins = centredBins(90 / OFFSET_STEP, OFFSET_STEP);
  for (const { result: r } of entries) {
    // A prediction's answer and expected value are angles (readAnswer, gradeAnswer).
    if (r.answered && typeof r.answer === 'number' && typeof r.expected === 'number') {
      addTo(bins, r.answer - r.expected, OFFSET_STEP, r.correct);
    }
  }
  return { step: OFFSET_STEP, bins };
}

/**
 * A summary per item of the sheet. grades: gradeClass's { ok: true, … }; gradebook: its
 * buildGradebook, whose counted rows are the students summarised (without it, every hand-in graded).
 * @param {{ sheet: import('../readSheet.js').Sheet, graded: readonly import('./gradeClass.js').Graded[] }} grades
 * @param {{ rows: { key: number, counted: boolean }[] }} [gradebook]
 * @returns {QuestionSummary[]}
 */
export function summarizeQuestions(grades, gradebook) {
  const students = gradebook ? gradebook.rows.filter((row) => row.counted).map((row) => grades.graded[row.key]) : grades.graded;
  return grades.sheet.items.map((item, i) => {
    const question = knownQuestion(item.question);
    const entries = students.map(({ source, result }) => ({ source, result: result.results[i] }));
    const right = entries.filter((e) => e.result.correct).length;
    const unanswered = entries.filter((e) => !e.result.answered).length;
    // The one instance a card shows: the first student's parameters.
    const params = entries[0]?.result.params;
    const same = JSON.stringify(params);
    /** @type {SummaryBase & { kind: string }} */
    const base = {
      item: i, question: question.id, kind: question.kind,
      unit: question.kind === 'choice' ? null : question.unit, tolerance: question.kind === 'choice' ? null : question.tolerance,
      students: entries.length, right, wrong: entries.length - right - unanswered, unanswered,
      shareRight: entries.length ? right / entries.length : null,
      shown: params ? { params, sameForAll: entries.every((e) => JSON.stringify(e.result.params) === same) } : null,
    };
    /** @type {QuestionSummary} */
    const summary = question.kind === 'choice' ? { ...base, kind: 'choice', options: choiceSummary(question, entries, params) }
      : question.kind === 'numeric' ? { ...base, kind: 'numeric', ...numericSummary(question, entries, params) }
      : { ...base, kind: 'predict', offset: predictSummary(entries) };
    return summary;
  });
}
