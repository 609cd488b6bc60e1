// @ts-check
// What a graded class can be saved as, with a line on what each file is for: the gradebook as CSV
// (commas for a spreadsheet in English and for scripts, semicolons for one that writes 87,5),
// the class view to open again, and the grades as the file an LMS imports (Moodle's offline grading
// worksheet, Canvas's gradebook import: lmsGrades.js). An LMS finds each student by their id there,
// which only a hand-in's path in that LMS's download gives: who has none is listed after the file
// is saved, to be graded by hand.
import { button, el } from '../../../ui/el.js';
import { downloadText } from '../../../host/exporters.js';
import { fileSlug, fixed } from '../../../ui/format.js';
import { gradebookToCsv, cellsToCsv } from '../../class/gradebookToCsv.js';
import { writeClassFile } from '../../class/classFile.js';
import { canvasImport, moodleWorksheet } from '../../class/lmsGrades.js';
import { field } from '../../../ui/formParts.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../../i18n/messages.js';

const t = messages('class', english);
const CSV_TYPE = 'text/csv;charset=utf-8';
// Each LMS's button and what it says are the catalogue's lms.<key>.button and lms.<key>.about; the
// files' own column names are the LMS's (lmsGrades.js).
/** @type {Record<'moodle' | 'canvas', { file: string, make: typeof moodleWorksheet }>} */
const LMS = {
  moodle: { file: 'moodle-grading-worksheet', make: moodleWorksheet },
  canvas: { file: 'canvas-grades', make: canvasImport },
};

const nameOf = (/** @type {import('../../class/buildGradebook.js').Row} */ row) => row.name || row.lmsName || row.source;
/** A count for a plural message: the number that picks the form, and the number shown. */
const many = (/** @type {number} */ count) => ({ count, n: fixed(count, 0) });

/**
 * Why a student is not in an LMS's file, in a sentence.
 * @param {string} lms
 * @param {import('../../class/lmsGrades.js').LeftOut} left
 */
function leftText(lms, left) {
  const name = nameOf(left.row);
  if (left.why === 'two-ids') return t('lms.twoIds', { lms, name, ids: left.ids.join(', ') });
  if (left.why === 'shared-id') return t('lms.sharedId', { lms, name, id: left.id, others: left.others.map(nameOf).join(', ') });
  return t('lms.noId', { lms, name, source: left.row.source });
}

/**
 * The export tools for a class view (buildClassView's result): { files (the gradebook and the view,
 * shown above the gradebook), lms (the LMS's files, below it) }.
 * @param {{ gradebook: import('../../class/buildGradebook.js').Gradebook, sheet: unknown,
 *   handIns: import('../../class/readClassHandIns.js').HandIn[] }} view
 */
export function buildExportTools(view) {
  const { gradebook } = view;
  const slug = fileSlug(gradebook.title);
  const files = el('div', 'hw-exports');
  const tools = el('div', 'hw-class-tools');
  const csv = button(t('exports.csv'));
  const semicolons = button(t('exports.semicolons'));
  const keep = button(t('exports.keep'));
  tools.append(csv, semicolons, keep);
  csv.addEventListener('click', () => downloadText(`${slug}-gradebook.csv`, gradebookToCsv(gradebook, { includeSuperseded: true }),
    CSV_TYPE));
  semicolons.addEventListener('click', () => downloadText(`${slug}-gradebook-semicolons.csv`,
    gradebookToCsv(gradebook, { includeSuperseded: true, semicolons: true }), CSV_TYPE));
  keep.addEventListener('click', () => downloadText(`${slug}-class.json`, writeClassFile({ sheet: view.sheet, handIns: view.handIns }),
    'application/json'));
  const about = el('ul', 'hw-export-about');
  about.append(el('li', null, t('exports.csvAbout')), el('li', null, t('exports.semicolonsAbout')), el('li', null, t('exports.keepAbout')));

  const lms = el('fieldset', 'hw-lms-export');
  lms.append(el('legend', null, t('lms.legend')));
  const outOf = el('input');
  outOf.type = 'number';
  outOf.min = '1';
  outOf.step = 'any';
  outOf.value = '100';
  const status = el('p', 'hw-lms-status');
  status.setAttribute('role', 'status');
  const leftList = el('ul', 'hw-lms-left');
  const lmsTools = el('div', 'hw-class-tools');
  const lmsAbout = el('ul', 'hw-export-about');
  for (const [key, lmsEntry] of Object.entries(LMS)) {
    const save = button(t(`lms.${key}.button`));
    save.addEventListener('click', () => {
      const max = Number(outOf.value);
      if (!(max > 0 && max <= 1e6)) {
        status.textContent = t('lms.badOutOf');
        leftList.replaceChildren();
        return;
      }
      const made = lmsEntry.make(gradebook, { outOf: max });
      if (made.students.length) downloadText(`${slug}-${lmsEntry.file}.csv`, cellsToCsv(made.cells), CSV_TYPE);
      const saved = [t('lms.saved', { lms: key, ...many(made.students.length), outOf: outOf.value })];
      if (made.left.length) saved.push(t('lms.left', many(made.left.length)));
      status.textContent = made.students.length ? saved.join(' ') : t('lms.nothing', { lms: key });
      leftList.replaceChildren(...made.left.map((left) => el('li', null, leftText(key, left))));
    });
    lmsTools.append(save);
    lmsAbout.append(el('li', null, t(`lms.${key}.about`)));
  }
  lms.append(field(t('lms.outOf'), outOf), lmsTools, lmsAbout, status, leftList);
  files.append(tools, about);
  return { files, lms };
}
