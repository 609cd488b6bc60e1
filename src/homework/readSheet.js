// A homework sheet (what a lecturer composes) and a handed-in file (what a student exports), read
// from untrusted JSON: every field is checked, anything unexpected is refused with a reason, and a
// handed-in file is graded only by recomputing each answer from its seed (gradeAnswer.js).
import { questionById } from './questions.js';
import { gradeAnswer, questionParams } from './gradeAnswer.js';

export const SHEET_VERSION = 1;
const MAX_ITEMS = 40;
const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;

/** { ok: true, sheet } with the sheet's items normalised, or { ok: false, problems: [text] }. */
export function readSheet(data) {
  const problems = [];
  if (!data || typeof data !== 'object' || Array.isArray(data)) return { ok: false, problems: ['A sheet is a JSON object.'] };
  if (data.version !== SHEET_VERSION) problems.push(`version must be ${SHEET_VERSION}.`);
  if (!text(data.title, 200)) problems.push('title must be a text of 1 to 200 characters.');
  if (!Array.isArray(data.items) || data.items.length === 0 || data.items.length > MAX_ITEMS) {
    problems.push(`items must be a list of 1 to ${MAX_ITEMS} questions.`);
  } else {
    data.items.forEach((item, i) => {
      if (!questionById(item?.question)) problems.push(`item ${i + 1}: there is no question “${String(item?.question).slice(0, 40)}”.`);
    });
  }
  if (data.reveal !== undefined && !['after-answer', 'lecturer'].includes(data.reveal)) problems.push('reveal must be after-answer or lecturer.');
  if (problems.length) return { ok: false, problems };
  return {
    ok: true,
    sheet: {
      version: SHEET_VERSION,
      title: data.title,
      reveal: data.reveal ?? 'after-answer',
      items: data.items.map((item) => ({ question: item.question })),
    },
  };
}

/**
 * Grades a handed-in file { version, sheet, seed, answers: [answer per item], time } against the
 * sheet it names: { ok: true, score, total, results } or { ok: false, problems }. Any "correct" or
 * score the file carries is ignored.
 */
export function gradeHandIn(data) {
  if (!data || typeof data !== 'object' || Array.isArray(data)) return { ok: false, problems: ['A handed-in file is a JSON object.'] };
  const read = readSheet(data.sheet);
  const problems = read.ok ? [] : read.problems.map((p) => `sheet: ${p}`);
  if (!text(data.seed, 64)) problems.push('seed must be a text of 1 to 64 characters.');
  if (!Array.isArray(data.answers) || (read.ok && data.answers.length !== read.sheet.items.length)) problems.push('answers must hold one entry per question.');
  if (problems.length) return { ok: false, problems };
  const results = read.sheet.items.map((item, i) => {
    const question = questionById(item.question);
    const params = questionParams(question, data.seed);
    const raw = data.answers[i];
    const answer = typeof raw === 'string' || typeof raw === 'number' ? raw : raw?.value;
    return { question: question.id, params, ...gradeAnswer(question, params, typeof answer === 'string' ? answer.slice(0, 80) : answer) };
  });
  return { ok: true, title: read.sheet.title, seed: data.seed, score: results.filter((r) => r.correct).length, total: results.length, results };
}
