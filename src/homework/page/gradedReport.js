// @ts-check
// One graded hand-in as the lecturer reads it: a table of every question as that student saw it,
// their answer, the computed answer, and why. Shared by "Check a handed-in file" and the class
// view's per-student detail. Text only (textContent), never markup.
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { pageLocale } from '../../ui/safeLocale.js';
import { knownQuestion } from '../questions.js';
import { trueOption } from '../gradeAnswer.js';
import { formatValue } from '../formatAnswer.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/** @typedef {import('../questions.js').Question} Question */

/**
 * @param {Question} question
 * @param {{ answer: number | string | null }} result
 * @param {unknown} params
 */
function answerText(question, result, params) {
  if (result.answer === null) return '—';
  if (question.kind === 'choice') {
    // A choice's answer is one of its options (readAnswer keeps no other).
    const chosen = question.options(params).find((o) => o.id === result.answer);
    return chosen ? chosen.text(params) : String(result.answer);
  }
  // A typed answer is shown as it was typed; a prediction is an angle.
  return question.kind === 'numeric' || typeof result.answer !== 'number' ? String(result.answer) : formatValue(question, result.answer);
}

/**
 * @param {Question} question
 * @param {unknown} params
 */
function expectedText(question, params) {
  return question.kind === 'choice' ? trueOption(question, params).text(params) : formatValue(question, question.expected(params));
}

/**
 * A box that says what could not be used, as an alert.
 * @param {string} title
 * @param {readonly string[]} problems
 */
export function problemBox(title, problems) {
  const alert = el('div', 'notice notice-error');
  alert.setAttribute('role', 'alert');
  const list = el('ul');
  for (const p of problems) list.append(el('li', null, p));
  alert.append(el('strong', null, title), list);
  return alert;
}

/**
 * The report of one graded hand-in (gradeHandIn's result, or { ok: false, problems }): who, the
 * score, the sheet's fingerprint, and a row per question as that student saw it. against: which
 * sheet it was checked against: 'given' (the sheet the lecturer gave), 'named' (the one the file
 * names) or 'set' (the class's).
 * @param {string} label
 * @param {import('../gradeHandIn.js').GradedHandIn | { ok: false, problems: string[] }} graded
 * @param {{ against: 'given' | 'named' | 'set' }} options
 */
export function gradedReport(label, graded, { against }) {
  const box = el('section', 'hw-report');
  box.append(el('h3', 'hw-report-who', label)); // a student's name or a file's: words from outside
  if (!graded.ok) {
    box.append(problemBox(t('report.cannotCheck'), graded.problems));
    return box;
  }
  const score = el('p', 'hw-score', t('report.score', {
    title: graded.title, hasName: graded.name ? 'yes' : 'no', name: graded.name, seed: graded.seed,
    hasTime: graded.time ? 'yes' : 'no', time: graded.time ? new Date(graded.time).toLocaleString(pageLocale()) : '',
    score: graded.score, total: graded.total,
  }));
  score.setAttribute('role', 'status');
  const fingerprint = el('p', 'hw-meta', t('report.fingerprint', { fingerprint: graded.fingerprint, against }));
  const table = el('table', 'hw-report-table');
  const thead = el('thead');
  const tbody = el('tbody');
  table.append(thead, tbody);
  const head = el('tr');
  for (const column of ['number', 'question', 'answer', 'expected', 'result', 'tries']) {
    head.append(el('th', null, t(`report.column.${column}`)));
  }
  thead.append(head);
  graded.results.forEach((result, i) => {
    const question = knownQuestion(result.question);
    const row = el('tr', result.correct ? 'hw-row-right' : 'hw-row-wrong');
    const prompt = el('td');
    setSubscripted(prompt, question.prompt(result.params));
    row.append(
      el('td', null, String(i + 1)),
      prompt,
      el('td', null, answerText(question, result, result.params)),
      el('td', null, expectedText(question, result.params)),
      el('td', null, t('report.result', {
        result: result.correct ? 'right' : result.answered ? 'wrong' : 'none', explanation: result.explanation,
      })),
      el('td', null, result.attempts === null ? '—' : String(result.attempts)),
    );
    tbody.append(row);
  });
  box.append(score, fingerprint, table);
  return box;
}
