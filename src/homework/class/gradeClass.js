// @ts-check
// Grading a class: every hand-in against the sheet the lecturer set, each by gradeHandIn (answers
// recomputed from the sheet, the seed and the answer; nothing a file says about its score is read).
// A hand-in for another sheet, another class seed, or data that is no hand-in is refused with its
// source and the reasons. The work is a generator that pauses between slices of about 40 ms (the
// slow first computations of each question are done one at a time first, so no slice holds several),
// so a page can grade on its own thread without a long task (gradeClass), or a worker can run it
// through (classWorker.js); gradeClassSync runs it to its end (tests, Node).
import { gradeHandIn, sheetFingerprint } from '../gradeHandIn.js';
import { expectedValue, questionParams, trueOption } from '../gradeAnswer.js';
import { knownQuestion } from '../questions.js';
import { readSheet } from '../readSheet.js';
import { HAND_IN_KIND } from '../sheetCodes.js';
import { rawText } from '../../host/params.js';
import { isObject, own } from '../../host/own.js';
import { CLASS_FILE_KIND } from './classFile.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/**
 * @typedef {{ source: string, data: unknown }} HandIn
 * @typedef {{ source: string, reason: string }} Refusal
 * @typedef {{ source: string, result: import('../gradeHandIn.js').GradedHandIn }} Graded  result: its sheet is the class's
 * @typedef {{ ok: true, sheet: import('../readSheet.js').Sheet, fingerprint: string, graded: Graded[], refused: Refusal[],
 *   problems?: undefined } | { ok: false, problems: string[] }} ClassGrades
 * @typedef {{ done: number, total: number }} Progress
 */

const t = messages('class', english);
const SLICE_MS = 40;

/**
 * Why `data` is not a hand-in at all, before grading (a sheet or a saved class view dropped among them), or null.
 * @param {unknown} data
 */
function notAHandIn(data) {
  if (!isObject(data)) return t('grade.notObject');
  const kind = own(data, 'kind');
  if (kind === CLASS_FILE_KIND) return t('grade.classView');
  if (kind !== undefined && kind !== HAND_IN_KIND) return t('grade.otherKind', { kind: rawText(kind) });
  if (Object.hasOwn(data, 'items') && !Object.hasOwn(data, 'answers')) return t('grade.sheet');
  return null;
}

/**
 * The cold work of grading, a question at a time: the first time a question meets its parameters,
 * its expected value (or the option that holds) is computed, and for a few that takes tens of
 * milliseconds (the asphalt question bisects over the panel's scene; Schlick's worst error sweeps a
 * scene): together well over 100 ms in a class's first hand-in. Done here once per question and
 * parameters, with a step after each, a slice can end between them; grading then finds them
 * remembered (gradeAnswer.js). Yields after each computation; hand-ins without a usable seed are
 * left to gradeHandIn to refuse.
 * @param {import('../readSheet.js').Sheet} sheet
 * @param {readonly unknown[]} list
 */
function* primeQuestions(sheet, list) {
  const questions = sheet.items.map((item) => knownQuestion(item.question));
  const seen = new Set();
  for (const item of list) {
    const data = isObject(item) ? own(item, 'data') : undefined;
    const seed = isObject(data) ? own(data, 'seed') : undefined;
    if (typeof seed !== 'string' || seed.length === 0 || seed.length > 64) continue;
    for (const question of questions) {
      const params = questionParams(question, seed);
      const key = `${question.id}\u0000${JSON.stringify(params)}`;
      if (seen.has(key)) continue;
      seen.add(key);
      try {
        if (question.kind !== 'choice') expectedValue(question, params);
        else for (const option of [trueOption(question, params), ...question.options(params)]) option.why(params);
      } catch { /* gradeHandIn meets it again and says so */ }
      yield;
    }
  }
}

/**
 * The steps of grading: yields { done, total } after each slice of about `sliceMs` and returns the
 * class's grades. sheet: the sheet the lecturer set (its JSON, read here once; required).
 * @param {unknown} sheet
 * @param {HandIn[]} handIns
 * @param {{ sliceMs?: number, now?: () => number }} [options]
 * @returns {Generator<Progress, ClassGrades, void>}
 */
export function* gradeClassSteps(sheet, handIns, { sliceMs = SLICE_MS, now = () => performance.now() } = {}) {
  const read = readSheet(sheet);
  if (!read.ok) return { ok: false, problems: read.problems.map((problem) => t('grade.sheetSet', { problem })) };
  const expected = read.sheet;
  const list = Array.isArray(handIns) ? handIns : [];
  /** @type {Graded[]} */
  const graded = [];
  /** @type {Refusal[]} */
  const refused = [];
  let sliceStart = now();
  const due = () => now() - sliceStart >= sliceMs;
  const priming = primeQuestions(expected, list);
  while (!priming.next().done) {
    if (due()) {
      yield { done: 0, total: list.length };
      sliceStart = now();
    }
  }
  for (let i = 0; i < list.length; i += 1) {
    const item = list[i];
    const given = own(item, 'source');
    const source = typeof given === 'string' ? given : t('source.handIn', { number: i + 1 });
    const data = own(item, 'data');
    const reason = notAHandIn(data);
    if (reason) refused.push({ source, reason });
    else {
      /** @type {ReturnType<typeof gradeHandIn>} */
      let result;
      try {
        result = gradeHandIn(data, { expected });
      } catch (error) {
        result = { ok: false, problems: [t('grade.notGraded', { error: error instanceof Error ? error.message : t('anError') })] };
      }
      // The hand-in's sheet is the class's (the fingerprints agree): one shared object, not 500 copies.
      if (result.ok) graded.push({ source, result: { ...result, sheet: expected } });
      else refused.push({ source, reason: result.problems.join(' ') });
    }
    if (i + 1 < list.length && due()) {
      yield { done: i + 1, total: list.length };
      sliceStart = now();
    }
  }
  return { ok: true, sheet: expected, fingerprint: sheetFingerprint(expected), graded, refused };
}

/** The next task: the page's other work (input, painting) runs before grading goes on. */
function nextTask() {
  // scheduler.yield (Chromium 129 and later) is not in TypeScript's DOM types yet.
  const { scheduler } = /** @type {typeof globalThis & { scheduler?: { yield?: () => Promise<void> } }} */ (globalThis);
  if (typeof scheduler?.yield === 'function') return scheduler.yield();
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/**
 * Grades a class in slices: between slices it awaits `pause` (the next task) and reports progress;
 * an aborted `signal` stops it (the promise rejects with the signal's reason).
 * @param {unknown} sheet
 * @param {HandIn[]} handIns
 * @param {{ sliceMs?: number, onProgress?: (progress: Progress) => void, signal?: AbortSignal, pause?: () => Promise<unknown> }} [options]
 * @returns {Promise<ClassGrades>}
 */
export async function gradeClass(sheet, handIns, { sliceMs, onProgress, signal, pause = nextTask } = {}) {
  const steps = gradeClassSteps(sheet, handIns, { sliceMs });
  for (;;) {
    signal?.throwIfAborted();
    const step = steps.next();
    if (step.done === true) return step.value;
    onProgress?.(/** @type {Progress} */ (step.value));
    await pause();
  }
}

/**
 * Grades a class at once (a worker, a test, Node).
 * @param {unknown} sheet
 * @param {HandIn[]} handIns
 * @returns {ClassGrades}
 */
export function gradeClassSync(sheet, handIns) {
  const steps = gradeClassSteps(sheet, handIns, { sliceMs: Infinity });
  for (;;) {
    const step = steps.next();
    if (step.done) return step.value;
  }
}
