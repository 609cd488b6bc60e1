// "Check a handed-in file": the lecturer pastes a code or picks files, and every answer is graded
// again from the sheet, the seed and the answer alone (gradeHandIn.js); whatever the file says
// about its own score is ignored. Given the sheet that was set (its link or file), a hand-in made
// for any other sheet is refused. Each file gets a table: the question as that student saw it,
// their answer, the computed answer, and why.
import { el } from '../../ui/el.js';
import { gradeHandIn } from '../gradeHandIn.js';
import { handInFromText } from '../sheetCodes.js';
import { readSetSheet } from './readSetSheet.js';
import { gradedReport, problemBox } from './gradedReport.js';
import { button, field, readTextFile, titledSection } from './formParts.js';

/** The graded report of one handed-in file, or its problems. */
function report(label, text, expected, read = handInFromText(text)) {
  let graded = read.ok ? null : read;
  try {
    graded ??= gradeHandIn(read.data, { expected });
  } catch (error) {
    graded = { ok: false, problems: [`A question could not be graded: ${error.message}`] };
  }
  return gradedReport(label, graded, { against: expected ? 'the sheet given' : 'the sheet the file names' });
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
    el('p', null, 'Every answer is recomputed from the sheet, the seed and the answer; nothing the file says about being right is read. '
      + 'For a whole class at once, with a gradebook, use “Grade a class” below.'),
    field('The sheet you set (optional, recommended)', sheet),
    field('Paste a hand-in code (FLH1.…) or a handed-in file’s text', code), check,
    field('Or choose handed-in files', files), results);
  root.append(section);

  const withExpected = (grade) => {
    const expected = readSetSheet(sheet.value);
    if (!expected.ok) results.replaceChildren(problemBox('The sheet to check against cannot be used:', expected.problems));
    else results.replaceChildren(...grade(expected.sheet));
  };
  check.addEventListener('click', () => withExpected((expected) => [report('Pasted code', code.value, expected)]));
  files.addEventListener('change', async () => {
    const picked = await Promise.all([...files.files].map(async (file) => ({ file, read: await readTextFile(file) })));
    withExpected((expected) => picked.map(({ file, read }) => (read.ok
      ? report(file.name, read.text, expected)
      : report(file.name, '', expected, read))));
  });
  return { check: (text) => { code.value = text; check.click(); } };
}
