// @ts-check
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

/**
 * The graded report of one handed-in file, or its problems.
 * @param {string} label
 * @param {string} text
 * @param {import('../readSheet.js').Sheet | null} expected
 * @param {import('../sheetCodes.js').Decoded | { ok: false, problems: string[] }} [read]
 */
function report(label, text, expected, read = handInFromText(text)) {
  /** @type {Parameters<typeof gradedReport>[1]} */
  let graded;
  if (!read.ok) graded = { ok: false, problems: read.problems };
  else {
    try {
      graded = gradeHandIn(read.data, { expected });
    } catch (error) {
      graded = { ok: false, problems: [t('grade.notGraded', { error: error instanceof Error ? error.message : String(error) })] };
    }
  }
  return gradedReport(label, graded, { against: expected ? 'given' : 'named' });
}

/**
 * The checker's section in `root`; check(text) checks pasted text as its button does.
 * @param {Element} root
 */
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

  /** @param {(expected: import('../readSheet.js').Sheet | null) => Node[]} grade */
  const withExpected = (grade) => {
    const expected = readSetSheet(sheet.value);
    if (!expected.ok) results.replaceChildren(problemBox(t('checker.sheetUnusable'), expected.problems));
    else results.replaceChildren(...grade(expected.sheet));
  };
  check.addEventListener('click', () => withExpected((expected) => [report(t('checker.pasted'), code.value, expected)]));
  files.addEventListener('change', async () => {
    const picked = await Promise.all([...(files.files ?? [])].map(async (file) => ({ file, read: await readTextFile(file) })));
    withExpected((expected) => picked.map(({ file, read }) => (read.ok
      ? report(file.name, read.text, expected)
      : report(file.name, '', expected, { ok: false, problems: read.problems }))));
  });
  return { check: (/** @type {string} */ text) => { code.value = text; check.click(); } };
}
