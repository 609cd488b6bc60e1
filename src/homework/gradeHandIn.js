// Grading a handed-in file: every answer is recomputed from the sheet, the seed and the answer
// (gradeAnswer.js); a score or a "correct" the file carries is never read. The file also says
// which sheet it answers, and a student could edit that; so the lecturer can give the sheet they
// set, and a file made for any other sheet (a copy with items dropped, another class seed) is
// refused. Each report shows the sheet's fingerprint either way.
import { questionById } from './questions.js';
import { gradeAnswer, questionParams, readAnswer } from './gradeAnswer.js';
import { SHEET_VERSION, readSheet } from './readSheet.js';
import { hashSeed } from './seededRandom.js';
import { rawText } from '../host/params.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;

/** A short fingerprint of a sheet as read by readSheet (its questions, order, states, seed, title). */
export const sheetFingerprint = (sheet) => hashSeed(JSON.stringify(sheet)).toString(36).padStart(7, '0');

/**
 * Grades { version, sheet, seed, name, answers: [answer per item], attempts?, time }.
 * expected: the sheet the lecturer set, when given. Returns { ok: true, title, sheet, fingerprint,
 * seed, name, time, score, total, results } or { ok: false, problems }.
 */
export function gradeHandIn(data, { expected = null } = {}) {
  if (!data || typeof data !== 'object' || Array.isArray(data)) return { ok: false, problems: [t('handIn.notObject')] };
  const read = readSheet(data.sheet);
  const problems = read.ok ? [] : read.problems.map((problem) => t('handIn.sheet', { problem }));
  if (data.version !== SHEET_VERSION) problems.push(t('sheet.version', { version: SHEET_VERSION }));
  if (!text(data.seed, 64)) problems.push(t('handIn.seed'));
  if (!Array.isArray(data.answers) || (read.ok && data.answers.length !== read.sheet.items.length)) problems.push(t('handIn.answers'));
  if (read.ok && read.sheet.seed !== undefined && data.seed !== read.sheet.seed) {
    problems.push(t('handIn.classSeed', { classSeed: read.sheet.seed, seed: rawText(data.seed, 64) }));
  }
  if (read.ok && expected && sheetFingerprint(read.sheet) !== sheetFingerprint(expected)) {
    problems.push(t('handIn.otherSheet', { fingerprint: sheetFingerprint(read.sheet), expected: sheetFingerprint(expected) }));
  }
  if (problems.length) return { ok: false, problems };
  const attempts = Array.isArray(data.attempts) ? data.attempts : [];
  const results = read.sheet.items.map((item, i) => {
    const question = questionById(item.question);
    const params = questionParams(question, data.seed);
    const raw = data.answers[i];
    const answer = readAnswer(question, params, typeof raw === 'string' || typeof raw === 'number' ? raw : raw?.value);
    const tries = Number.isInteger(attempts[i]) && attempts[i] >= 0 ? attempts[i] : null;
    return { question: question.id, params, answer, attempts: tries, ...gradeAnswer(question, params, answer) };
  });
  const name = text(data.name, 100) ? data.name : '';
  const time = text(data.time, 40) && !Number.isNaN(Date.parse(data.time)) ? data.time : null;
  return {
    ok: true, title: read.sheet.title, sheet: read.sheet, fingerprint: sheetFingerprint(read.sheet), seed: data.seed, name, time,
    score: results.filter((r) => r.correct).length, total: results.length, results,
  };
}
