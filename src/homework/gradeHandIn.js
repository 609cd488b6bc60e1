// @ts-check
// Grading a handed-in file: every answer is recomputed from the sheet, the seed and the answer
// (gradeAnswer.js); a score or a "correct" the file carries is never read. The file also says
// which sheet it answers, and a student could edit that; so the lecturer can give the sheet they
// set, and a file made for any other sheet (a copy with items dropped, another class seed) is
// refused. Each report shows the sheet's fingerprint either way.
import { knownQuestion } from './questions.js';
import { gradeAnswer, questionParams, readAnswer } from './gradeAnswer.js';
import { SHEET_VERSION, readSheet } from './readSheet.js';
import { hashSeed } from './seededRandom.js';
import { rawText } from '../host/params.js';
import { isObject, own } from '../host/own.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

/** @type {(v: unknown, max: number) => v is string} */
const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;

/** @typedef {import('./readSheet.js').Sheet} Sheet */
/**
 * One answer of a hand-in, graded again: the question's id, its parameters from the seed, the
 * answer as it reads for the question (readAnswer), the tries it took (null where the file says
 * none that can be used), and the grade.
 * @typedef {import('./gradeAnswer.js').Grade & { question: string, params: unknown, answer: number | string | null,
 *   attempts: number | null }} HandInResult
 */
/**
 * @typedef {{ ok: true, title: string, sheet: Sheet, fingerprint: string, seed: string, name: string, time: string | null,
 *   score: number, total: number, results: HandInResult[], problems?: undefined }} GradedHandIn
 */

/**
 * A short fingerprint of a sheet as read by readSheet (its questions, order, states, seed, title).
 * @param {Sheet} sheet
 */
export const sheetFingerprint = (sheet) => hashSeed(JSON.stringify(sheet)).toString(36).padStart(7, '0');

/**
 * Grades { version, sheet, seed, name, answers: [answer per item], attempts?, time }.
 * expected: the sheet the lecturer set, when given. Returns { ok: true, title, sheet, fingerprint,
 * seed, name, time, score, total, results } or { ok: false, problems }.
 * @param {unknown} data
 * @param {{ expected?: Sheet | null }} [options]
 * @returns {GradedHandIn | { ok: false, problems: string[] }}
 */
export function gradeHandIn(data, { expected = null } = {}) {
  if (!isObject(data)) return { ok: false, problems: [t('handIn.notObject')] };
  const field = (/** @type {string} */ key) => own(data, key);
  const read = readSheet(field('sheet'));
  const problems = read.ok ? [] : read.problems.map((problem) => t('handIn.sheet', { problem }));
  if (field('version') !== SHEET_VERSION) problems.push(t('sheet.version', { version: SHEET_VERSION }));
  const seed = field('seed');
  if (!text(seed, 64)) problems.push(t('handIn.seed'));
  const answers = field('answers');
  if (!Array.isArray(answers) || (read.ok && answers.length !== read.sheet.items.length)) problems.push(t('handIn.answers'));
  if (read.ok && read.sheet.seed !== undefined && seed !== read.sheet.seed) {
    problems.push(t('handIn.classSeed', { classSeed: read.sheet.seed, seed: rawText(seed, 64) }));
  }
  if (read.ok && expected && sheetFingerprint(read.sheet) !== sheetFingerprint(expected)) {
    problems.push(t('handIn.otherSheet', { fingerprint: sheetFingerprint(read.sheet), expected: sheetFingerprint(expected) }));
  }
  if (problems.length || !read.ok || !text(seed, 64) || !Array.isArray(answers)) return { ok: false, problems };
  const rawAttempts = field('attempts');
  /** @type {unknown[]} */
  const attempts = Array.isArray(rawAttempts) ? rawAttempts : [];
  const results = read.sheet.items.map((item, i) => {
    const question = knownQuestion(item.question);
    const params = questionParams(question, seed);
    /** @type {unknown} */
    const raw = answers[i];
    const answer = readAnswer(question, params, typeof raw === 'string' || typeof raw === 'number' ? raw
      : own(raw, 'value'));
    const tried = attempts[i];
    const tries = typeof tried === 'number' && Number.isInteger(tried) && tried >= 0 ? tried : null;
    return { question: question.id, params, answer, attempts: tries, ...gradeAnswer(question, params, answer) };
  });
  const rawName = field('name');
  const name = text(rawName, 100) ? rawName : '';
  const rawTime = field('time');
  const time = text(rawTime, 40) && !Number.isNaN(Date.parse(rawTime)) ? rawTime : null;
  return {
    ok: true, title: read.sheet.title, sheet: read.sheet, fingerprint: sheetFingerprint(read.sheet), seed, name, time,
    score: results.filter((r) => r.correct).length, total: results.length, results,
  };
}
