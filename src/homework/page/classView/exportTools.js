// What a graded class can be saved as, with a line on what each file is for: the gradebook as CSV
// (commas for a spreadsheet in English and for scripts, semicolons for one that writes 87,5),
// the class view to open again, and the grades as the file an LMS imports (Moodle's offline grading
// worksheet, Canvas's gradebook import: lmsGrades.js). An LMS finds each student by their id there,
// which only a hand-in's path in that LMS's download gives: who has none is listed after the file
// is saved, to be graded by hand.
import { button, el } from '../../../ui/el.js';
import { downloadText } from '../../../host/exporters.js';
import { fileSlug } from '../../../ui/format.js';
import { gradebookToCsv, cellsToCsv } from '../../class/gradebookToCsv.js';
import { writeClassFile } from '../../class/classFile.js';
import { canvasImport, moodleWorksheet } from '../../class/lmsGrades.js';
import { field } from '../formParts.js';

const CSV_TYPE = 'text/csv;charset=utf-8';
const LMS = {
  moodle: {
    button: 'Moodle grading worksheet', file: 'moodle-grading-worksheet', id: 'participant number', make: moodleWorksheet,
    about: 'Moodle: turn on the assignment’s “Offline grading worksheet” feedback type, then Upload grading worksheet. '
      + 'Moodle reads the column headings in the language its pages are in, so upload it with Moodle set to English. '
      + 'Students are found by the participant number in the download’s folder names.',
  },
  canvas: {
    button: 'Canvas gradebook import', file: 'canvas-grades', id: 'user id', make: canvasImport,
    about: 'Canvas: Grades, then Import. Students are found by the user id in the download’s file names; the column '
      + 'is named after the sheet, and Canvas asks whether it is a new assignment or one you have.',
  },
};
const NAMES = { moodle: 'Moodle', canvas: 'Canvas' };

const nameOf = (row) => row.name || row.lmsName || row.source;
const students = (n) => `${n} student${n === 1 ? '' : 's'}`;

/** Why a student is not in an LMS's file, in a sentence. */
function leftText(lms, left) {
  const what = `${NAMES[lms]} ${LMS[lms].id}`;
  if (left.why === 'two-ids') return `${nameOf(left.row)}: handed in under two ${what}s (${left.ids.join(', ')}).`;
  if (left.why === 'shared-id') return `${nameOf(left.row)}: ${what} ${left.id} is also on the hand-in of `
    + `${left.others.map(nameOf).join(', ')}.`;
  return `${nameOf(left.row)}: no ${what} in the path of their hand-in (${left.row.source}).`;
}

/**
 * The export tools for a class view (buildClassView's result): { files (the gradebook and the view,
 * shown above the gradebook), lms (the LMS's files, below it) }.
 * @param {any} view
 */
export function buildExportTools(view) {
  const { gradebook } = view;
  const slug = fileSlug(gradebook.title);
  const files = el('div', 'hw-exports');
  const tools = el('div', 'hw-class-tools');
  const csv = button('Export CSV');
  const semicolons = button('Export CSV with semicolons');
  const keep = button('Save the class view');
  tools.append(csv, semicolons, keep);
  csv.addEventListener('click', () => downloadText(`${slug}-gradebook.csv`, gradebookToCsv(gradebook, { includeSuperseded: true }),
    CSV_TYPE));
  semicolons.addEventListener('click', () => downloadText(`${slug}-gradebook-semicolons.csv`,
    gradebookToCsv(gradebook, { includeSuperseded: true, semicolons: true }), CSV_TYPE));
  keep.addEventListener('click', () => downloadText(`${slug}-class.json`, writeClassFile({ sheet: view.sheet, handIns: view.handIns }),
    'application/json'));
  const about = el('ul', 'hw-export-about');
  about.append(
    el('li', null, 'Export CSV: every hand-in with its marks per question, for a spreadsheet in English or a script '
      + '(commas between cells, a point in 87.5, times in UTC).'),
    el('li', null, 'Export CSV with semicolons: the same, for Excel or LibreOffice in German, French and other languages '
      + 'that write 87,5 (semicolons between cells, a comma in 87,5, times in this computer’s time zone); '
      + 'the other file opens there in one column.'),
    el('li', null, 'Save the class view: the sheet and the hand-ins, to open here again later; every answer is graded again then.'),
  );

  const lms = el('fieldset', 'hw-lms-export');
  lms.append(el('legend', null, 'Grades back into the LMS'));
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
    const save = button(lmsEntry.button);
    save.addEventListener('click', () => {
      const max = Number(outOf.value);
      if (!(max > 0 && max <= 1e6)) {
        status.textContent = 'Give the assignment’s maximum grade as a number above 0.';
        leftList.replaceChildren();
        return;
      }
      const made = lmsEntry.make(gradebook, { outOf: max });
      if (made.students.length) downloadText(`${slug}-${lmsEntry.file}.csv`, cellsToCsv(made.cells), CSV_TYPE);
      status.textContent = made.students.length
        ? `Saved for ${NAMES[key]}: ${students(made.students.length)}, graded out of ${outOf.value}.`
          + `${made.left.length ? ` Not in the file, to grade by hand: ${students(made.left.length)}.` : ''}`
        : `Nothing saved: no hand-in came with a ${NAMES[key]} ${lmsEntry.id} (it is in the names of the LMS’s download).`;
      leftList.replaceChildren(...made.left.map((left) => el('li', null, leftText(key, left))));
    });
    lmsTools.append(save);
    lmsAbout.append(el('li', null, lmsEntry.about));
  }
  lms.append(field('Out of: the assignment’s maximum grade in the LMS', outOf), lmsTools, lmsAbout, status, leftList);
  files.append(tools, about);
  return { files, lms };
}
