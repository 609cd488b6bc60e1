// One graded hand-in as the lecturer reads it: a table of every question as that student saw it,
// their answer, the computed answer, and why. Shared by "Check a handed-in file" and the class
// view's per-student detail. Text only (textContent), never markup.
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { pageLocale } from '../../ui/safeLocale.js';
import { questionById } from '../questions.js';
import { trueOption } from '../gradeAnswer.js';
import { formatValue } from '../formatAnswer.js';

function answerText(question, result, params) {
  if (result.answer === null) return '—';
  if (question.kind === 'choice') return question.options(params).find((o) => o.id === result.answer).text(params);
  return question.kind === 'numeric' ? result.answer : formatValue(question, result.answer);
}

function expectedText(question, params) {
  return question.kind === 'choice' ? trueOption(question, params).text(params) : formatValue(question, question.expected(params));
}

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
 * sheet it was checked against, in words.
 */
export function gradedReport(label, graded, { against }) {
  const box = el('section', 'hw-report');
  box.append(el('h3', null, label));
  if (!graded.ok) {
    box.append(problemBox('This cannot be checked:', graded.problems));
    return box;
  }
  const who = graded.name || 'no name given';
  const when = graded.time ? new Date(graded.time).toLocaleString(pageLocale()) : 'no time given';
  const score = el('p', 'hw-score', `${graded.title}: ${who}, seed ${graded.seed}, handed in ${when}. `
    + `Score ${graded.score} of ${graded.total}, recomputed.`);
  score.setAttribute('role', 'status');
  const fingerprint = el('p', 'hw-meta', `Sheet fingerprint ${graded.fingerprint} (checked against ${against}).`);
  const table = el('table', 'hw-report-table');
  table.append(el('thead'), el('tbody'));
  const head = el('tr');
  const columns = ['#', 'Question (as this student saw it)', 'Answer', 'Computed answer', 'Result', 'Tries'];
  for (const h of columns) head.append(el('th', null, h));
  table.tHead.append(head);
  graded.results.forEach((result, i) => {
    const question = questionById(result.question);
    const row = el('tr', result.correct ? 'hw-row-right' : 'hw-row-wrong');
    const prompt = el('td');
    setSubscripted(prompt, question.prompt(result.params));
    row.append(
      el('td', null, String(i + 1)),
      prompt,
      el('td', null, answerText(question, result, result.params)),
      el('td', null, expectedText(question, result.params)),
      el('td', null, `${result.correct ? 'right' : result.answered ? 'wrong' : 'no answer'}: ${result.explanation}`),
      el('td', null, result.attempts === null ? '—' : String(result.attempts)),
    );
    table.tBodies[0].append(row);
  });
  box.append(score, fingerprint, table);
  return box;
}
