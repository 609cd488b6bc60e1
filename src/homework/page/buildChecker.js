// "Check a handed-in file": the lecturer pastes a code or picks files, and every answer is graded
// again from the sheet, the seed and the answer alone (gradeHandIn.js); whatever the file says
// about its own score is ignored. Given the sheet that was set (its link or file), a hand-in made
// for any other sheet is refused. Each file gets a table: the question as that student saw it,
// their answer, the computed answer, and why.
import { button, el } from '../../ui/el.js';
import { gradeHandIn } from '../gradeHandIn.js';
import { handInFromText } from '../sheetCodes.js';
import { readSetSheet } from './readSetSheet.js';
import { gradedReport, problemBox } from './gradedReport.js';
import { field, readTextFile, titledSection } from '../../ui/formParts.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

/** The graded report of one handed-in file, or its problems. */
function report(label, text, expected, read = handInFromText(text)) {
  let graded = read.ok ? null : read;
  try {
    graded ??= gradeHandIn(read.data, { expected });
  } catch (error) {
    graded = { ok: false, problems: [t('grade.notGraded', { error: error.message })] };
  }
  return gradedReport(label, graded, { against: expected ? 'given' : 'named' });
}

export function buildChecker(root) {
  const { section, heading } = titledSection('hw-checker', 'checker-title', t('checker.title'));
  const sheet = el('input');
  sheet.type = 'text';
  sheet.placeholder = t('checker.sheetPlaceholder');
  const code = el('textarea');
  code.rows = 4;
  const check = button(t('checker.check'));
  const files = el('input');
  files.type = 'file';
  files.accept = '.json,application/json';
  files.multiple = true;
  const results = el('div', 'hw-reports');
  section.append(heading, el('p', null, t('checker.intro')), field(t('checker.sheet'), sheet), field(t('checker.paste'), code), check,
    field(t('checker.files'), files), results);
  root.append(section);

  const withExpected = (grade) => {
    const expected = readSetSheet(sheet.value);
    if (!expected.ok) results.replaceChildren(problemBox(t('checker.sheetUnusable'), expected.problems));
    else results.replaceChildren(...grade(expected.sheet));
  };
  check.addEventListener('click', () => withExpected((expected) => [report(t('checker.pasted'), code.value, expected)]));
  files.addEventListener('change', async () => {
    const picked = await Promise.all([...files.files].map(async (file) => ({ file, read: await readTextFile(file) })));
    withExpected((expected) => picked.map(({ file, read }) => (read.ok
      ? report(file.name, read.text, expected)
      : report(file.name, '', expected, read))));
  });
  return { check: (text) => { code.value = text; check.click(); } };
}
