// "Check a handed-in file": the lecturer pastes a code or picks files, and every answer is graded
// again from the sheet, the seed and the answer alone (gradeHandIn); whatever the file says about
// its own score is ignored. Each file gets a table: the question as that student saw it, their
// answer, the computed answer, and why.
import { el } from '../../ui/el.js';
import { questionById } from '../questions.js';
import { gradeHandIn } from '../readSheet.js';
import { handInFromText } from '../sheetCodes.js';
import { formatValue } from './formatAnswer.js';
import { setSubscripted } from '../../ui/subscripts.js';

const MAX_FILE_BYTES = 1_000_000;

function answerText(question, result, params) {
  if (question.kind === 'choice') {
    const chosen = question.options(params).find((o) => o.id === result.answerId);
    return chosen ? chosen.text(params) : '—';
  }
  return result.answered ? formatValue(question, result.value) : '—';
}

function expectedText(question, result, params) {
  if (question.kind === 'choice') return question.options(params).find((o) => o.id === result.expected).text(params);
  return formatValue(question, result.expected);
}

/** The graded report of one handed-in file, or its problems. */
function report(label, text, read = handInFromText(text)) {
  const box = el('section', 'hw-report');
  box.append(el('h3', null, label));
  const graded = read.ok ? gradeHandIn(read.data) : read;
  if (!graded.ok) {
    const alert = el('div', 'notice notice-error');
    alert.setAttribute('role', 'alert');
    alert.append(el('strong', null, 'This cannot be checked:'));
    const list = el('ul');
    for (const p of graded.problems) list.append(el('li', null, p));
    alert.append(list);
    box.append(alert);
    return box;
  }
  const who = graded.name || 'no name given';
  const when = graded.time ? new Date(graded.time).toLocaleString() : 'no time given';
  const score = el('p', 'hw-score', `${graded.title}: ${who}, seed ${graded.seed}, handed in ${when}. Score ${graded.score} of ${graded.total}, recomputed.`);
  score.setAttribute('role', 'status');
  const table = el('table', 'hw-report-table');
  const head = el('tr');
  for (const h of ['#', 'Question (as this student saw it)', 'Answer', 'Computed answer', 'Result']) head.append(el('th', null, h));
  table.append(el('thead'), el('tbody'));
  table.tHead.append(head);
  graded.results.forEach((result, i) => {
    const question = questionById(result.question);
    const raw = read.data.answers[i];
    const row = el('tr', result.correct ? 'hw-row-right' : 'hw-row-wrong');
    const prompt = el('td');
    setSubscripted(prompt, question.prompt(result.params));
    const cells = [
      el('td', null, String(i + 1)),
      prompt,
      el('td', null, answerText(question, { ...result, answerId: typeof raw === 'string' ? raw : raw?.value }, result.params)),
      el('td', null, expectedText(question, result, result.params)),
      el('td', null, `${result.correct ? 'right' : result.answered ? 'wrong' : 'no answer'}: ${result.explanation}`),
    ];
    row.append(...cells);
    table.tBodies[0].append(row);
  });
  box.append(score, table);
  return box;
}

export function buildChecker(root) {
  const section = el('section', 'hw-checker');
  section.setAttribute('aria-labelledby', 'checker-title');
  const heading = el('h2', null, 'Check a handed-in file');
  heading.id = 'checker-title';
  const codeLabel = el('label', 'hw-field');
  const code = el('textarea');
  code.rows = 4;
  codeLabel.append(el('span', null, 'Paste a hand-in code (FLH1.…) or a handed-in file’s text'), code);
  const check = el('button', null, 'Check the code');
  check.type = 'button';
  const fileLabel = el('label', 'hw-field');
  const files = el('input');
  files.type = 'file';
  files.accept = '.json,application/json';
  files.multiple = true;
  fileLabel.append(el('span', null, 'Or choose handed-in files'), files);
  const results = el('div', 'hw-reports');
  section.append(heading, el('p', null, 'Every answer is recomputed from the sheet, the seed and the answer; nothing the file says about being right is read.'), codeLabel, check, fileLabel, results);
  root.append(section);

  check.addEventListener('click', () => results.replaceChildren(report('Pasted code', code.value)));
  files.addEventListener('change', async () => {
    const reports = [];
    for (const file of files.files) {
      if (file.size > MAX_FILE_BYTES) reports.push(report(file.name, '', { ok: false, problems: [`It is ${file.size} bytes: a handed-in file is a few kilobytes.`] }));
      else reports.push(report(file.name, await file.text()));
    }
    results.replaceChildren(...reports);
  });
  return { check: (text) => { code.value = text; check.click(); } };
}
