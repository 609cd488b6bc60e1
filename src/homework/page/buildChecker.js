// "Check a handed-in file": the lecturer pastes a code or picks files, and every answer is graded
// again from the sheet, the seed and the answer alone (gradeHandIn.js); whatever the file says
// about its own score is ignored. Given the sheet that was set (its link or file), a hand-in made
// for any other sheet is refused. Each file gets a table: the question as that student saw it,
// their answer, the computed answer, and why.
import { el } from '../../ui/el.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { questionById } from '../questions.js';
import { trueOption } from '../gradeAnswer.js';
import { gradeHandIn } from '../gradeHandIn.js';
import { readSheet } from '../readSheet.js';
import { handInFromText, sheetFromCode } from '../sheetCodes.js';
import { formatValue } from '../formatAnswer.js';
import { button, field, readTextFile, titledSection } from './formParts.js';

function answerText(question, result, params) {
  if (result.answer === null) return '—';
  if (question.kind === 'choice') return question.options(params).find((o) => o.id === result.answer).text(params);
  return question.kind === 'numeric' ? result.answer : formatValue(question, result.answer);
}

function expectedText(question, params) {
  return question.kind === 'choice' ? trueOption(question, params).text(params) : formatValue(question, question.expected(params));
}

function problemBox(title, problems) {
  const alert = el('div', 'notice notice-error');
  alert.setAttribute('role', 'alert');
  const list = el('ul');
  for (const p of problems) list.append(el('li', null, p));
  alert.append(el('strong', null, title), list);
  return alert;
}

/** The sheet to check against, from a link, a code or a sheet's JSON: { ok, sheet } or problems. */
function readExpected(text) {
  const raw = text.trim();
  if (!raw) return { ok: true, sheet: null };
  let data;
  if (raw.startsWith('{')) {
    try {
      data = JSON.parse(raw);
    } catch {
      return { ok: false, problems: ['The sheet to check against is not readable JSON.'] };
    }
  } else {
    let code = raw;
    try {
      code = new URL(raw, window.location.href).searchParams.get('sheet') ?? raw;
    } catch { /* not a link: a bare code */ }
    const decoded = sheetFromCode(code);
    if (!decoded.ok) return decoded;
    data = decoded.data;
  }
  const read = readSheet(data);
  return read.ok ? read : { ok: false, problems: read.problems.map((p) => `The sheet to check against: ${p}`) };
}

/** The graded report of one handed-in file, or its problems. */
function report(label, text, expected, read = handInFromText(text)) {
  const box = el('section', 'hw-report');
  box.append(el('h3', null, label));
  let graded = read.ok ? null : read;
  try {
    graded ??= gradeHandIn(read.data, { expected });
  } catch (error) {
    graded = { ok: false, problems: [`A question could not be graded: ${error.message}`] };
  }
  if (!graded.ok) {
    box.append(problemBox('This cannot be checked:', graded.problems));
    return box;
  }
  const who = graded.name || 'no name given';
  const when = graded.time ? new Date(graded.time).toLocaleString() : 'no time given';
  const against = expected ? 'the sheet given' : 'the sheet the file names';
  const score = el('p', 'hw-score', `${graded.title}: ${who}, seed ${graded.seed}, handed in ${when}. Score ${graded.score} of ${graded.total}, recomputed.`);
  score.setAttribute('role', 'status');
  const fingerprint = el('p', 'hw-meta', `Sheet fingerprint ${graded.fingerprint} (checked against ${against}).`);
  const table = el('table', 'hw-report-table');
  table.append(el('thead'), el('tbody'));
  const head = el('tr');
  for (const h of ['#', 'Question (as this student saw it)', 'Answer', 'Computed answer', 'Result', 'Tries']) head.append(el('th', null, h));
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

export function buildChecker(root) {
  const { section, heading } = titledSection('hw-checker', 'checker-title', 'Check a handed-in file');
  const sheet = el('input');
  sheet.type = 'text';
  sheet.placeholder = 'the sheet’s link (or its JSON): hand-ins for any other sheet are refused';
  const code = el('textarea');
  code.rows = 4;
  const check = button('Check the code');
  const files = el('input');
  files.type = 'file';
  files.accept = '.json,application/json';
  files.multiple = true;
  const results = el('div', 'hw-reports');
  section.append(heading,
    el('p', null, 'Every answer is recomputed from the sheet, the seed and the answer; nothing the file says about being right is read.'),
    field('The sheet you set (optional, recommended)', sheet),
    field('Paste a hand-in code (FLH1.…) or a handed-in file’s text', code), check,
    field('Or choose handed-in files', files), results);
  root.append(section);

  const withExpected = (grade) => {
    const expected = readExpected(sheet.value);
    if (!expected.ok) results.replaceChildren(problemBox('The sheet to check against cannot be used:', expected.problems));
    else results.replaceChildren(...grade(expected.sheet));
  };
  check.addEventListener('click', () => withExpected((expected) => [report('Pasted code', code.value, expected)]));
  files.addEventListener('change', async () => {
    const picked = await Promise.all([...files.files].map(async (file) => ({ file, read: await readTextFile(file) })));
    withExpected((expected) => picked.map(({ file, read }) => (read.ok ? report(file.name, read.text, expected) : report(file.name, '', expected, read))));
  });
  return { check: (text) => { code.value = text; check.click(); } };
}
