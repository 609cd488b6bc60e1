// Grades back into the LMS (src/homework/class/lmsGrades.js): Moodle's offline grading worksheet and
// Canvas's gradebook import, held to the columns their importers read (Moodle's
// mod/assign/feedback/offline/importgradeslib.php, Canvas's app/models/gradebook_importer.rb and
// its Instructor Guide), with each student's id taken from the path of their hand-ins.
import { describe, expect, it } from 'vitest';
import { strToU8, zipSync } from 'fflate';
import { buildClassView } from '../../src/homework/class/buildClassView.js';
import { canvasColumn, canvasImport, lmsStudents, moodleWorksheet } from '../../src/homework/class/lmsGrades.js';
import { cellsToCsv } from '../../src/homework/class/gradebookToCsv.js';
import { handInToCode, makeHandIn } from '../../src/homework/sheetCodes.js';

const sheet = { version: 1, title: 'Week 3', items: [{ question: 'exact-r' }, { question: 'metal-grazing' }] };
const handIn = (name, seed, time = '2026-01-10T10:00:00.000Z') => makeHandIn({ sheet, seed, name, answers: [null, null], time });
const json = (data) => strToU8(JSON.stringify(data));
/** A gradebook row as buildGradebook makes it, with the fields the LMS files read. */
const row = (key, name, score, more = {}) => ({
  key, name, lmsName: '', lms: '', lmsId: '', seed: 's', score, total: 8, percent: (100 * score) / 8, marks: [], tries: [],
  triesTotal: null, time: '2026-01-10T10:00:00.000Z', source: `${name}.json`, counted: true, flags: [], ...more,
});
const book = (rows) => ({ title: 'Week 3', fingerprint: 'f', classSeed: null, items: [], rows, students: rows.length, superseded: 0 });

// Moodle's importer: the columns it looks for by heading (English strings of mod/assign and core).
const MOODLE_REQUIRED = ['Identifier', 'Grade', 'Last modified (grade)'];
// Canvas's importer: header? and update_column_count in gradebook_importer.rb.
function canvasHeaderReads(header) {
  return /Student/.test(header[0]) && /ID/.test(header[1]) && /SIS\s+User\s+ID/.test(header[2]) && /SIS\s+Login\s+ID/.test(header[3])
    && /Section/.test(header[4]);
}

describe('Moodle\'s offline grading worksheet', () => {
  it('has the columns Moodle imports by, "Participant N" identifiers and grades out of the maximum grade', () => {
    const rows = [row(0, 'Ada', 7, { lms: 'moodle', lmsId: '100001' }), row(1, 'Bo, "B"', 8, { lms: 'moodle', lmsId: '100002' })];
    const now = new Date('2026-02-01T12:00:00.000Z');
    const { cells, left } = moodleWorksheet(book(rows), { outOf: 10, now });
    for (const column of MOODLE_REQUIRED) expect(cells[0]).toContain(column);
    const at = (r, column) => cells[r][cells[0].indexOf(column)];
    expect([at(1, 'Identifier'), at(1, 'Grade'), at(2, 'Identifier'), at(2, 'Grade')]).toEqual(['Participant 100001', '8.75', 'Participant 100002', '10']);
    expect(at(1, 'Last modified (grade)')).toBe('2026-02-01T12:00:00.000Z');
    expect(left).toEqual([]);
    // The importer strips "Participant " (Moodle's hiddenuser string) to find the number.
    expect(cells.slice(1).map((c) => c[0].slice('Participant '.length))).toEqual(['100001', '100002']);
    expect(cellsToCsv(cells).split('\r\n')[2]).toBe('Participant 100002,"Bo, ""B""",10,10,2026-01-10T10:00:00.000Z,2026-02-01T12:00:00.000Z');
    expect(moodleWorksheet(book(rows), { outOf: NaN }).cells[1][2]).toBe('87.5'); // no usable maximum: out of 100
  });
});

describe('Canvas\'s gradebook import', () => {
  it('has Student, ID, SIS User ID, SIS Login ID, Section, then the sheet\'s column and its points; a row per user id', () => {
    const rows = [row(0, 'Ada', 6, { lms: 'canvas', lmsId: '12345' }), row(1, '=cmd', 2, { lms: 'canvas', lmsId: '23456' })];
    const { cells } = canvasImport(book(rows));
    expect(cells[0]).toEqual(['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section', 'Week 3']);
    expect(canvasHeaderReads(cells[0])).toBe(true);
    expect(cells[1]).toEqual(['Points Possible', '', '', '', '', '100']);
    expect(cells.slice(2)).toEqual([['Ada', '12345', '', '', '', '75'], ["'=cmd", '23456', '', '', '', '25']]);
  });

  it('names the column so that Canvas reads it as a new assignment, not as an id or one of its own totals', () => {
    expect(canvasColumn('Homework (3)')).toBe('Homework [3]');
    expect(canvasColumn('Final Grade')).toBe('Final Grade (Fresnel Lab)');
    expect(canvasColumn('  ')).toBe('Fresnel Lab homework');
    expect(canvasColumn('Week 3 (Fresnel)')).toBe('Week 3 (Fresnel)');
  });
});

describe('who goes into an LMS\'s file', () => {
  it('a student\'s id from any of their hand-ins; no id, two ids or an id shared with another student: left out, with why', () => {
    const rows = [
      row(0, 'Ada', 5, { lms: 'moodle', lmsId: '1', counted: false }),
      row(1, 'Ada', 6, { flags: [{ kind: 'resubmitted', text: '', others: [0] }] }), // a later code, pasted: no path
      row(2, 'Bo', 4),
      row(3, 'Cy', 4, { lms: 'moodle', lmsId: '3', counted: false }),
      row(4, 'Cy', 4, { lms: 'moodle', lmsId: '4', flags: [{ kind: 'resubmitted', text: '', others: [3] }] }),
      row(5, 'Di', 4, { lms: 'moodle', lmsId: '5' }),
      row(6, 'Eve', 4, { lms: 'moodle', lmsId: '5' }),
      row(7, 'Fay', 4, { lms: 'canvas', lmsId: '7' }),
    ];
    const { students, left } = lmsStudents(book(rows), 'moodle');
    expect(students.map((s) => [s.id, s.row.name])).toEqual([['1', 'Ada']]);
    expect(left.map((l) => [l.row.name, l.why])).toEqual([['Bo', 'no-id'], ['Cy', 'two-ids'], ['Di', 'shared-id'], ['Eve', 'shared-id'],
      ['Fay', 'no-id']]);
  });

  it('from a Moodle and a Canvas download graded together, each file holds its LMS\'s students and names the rest', async () => {
    const zip = zipSync({
      'Ada Lovelace_100001_assignsubmission_file_': { 'h.json': json(handIn('Ada Lovelace', 'm1', '2026-01-09T10:00:00.000Z')) },
      'Bo Berg_100002_assignsubmission_onlinetext_': { 'onlinetext.html': strToU8(`<p>${handInToCode(handIn('', 'm2'))}</p>`) },
    });
    const view = await buildClassView({
      sheet, files: [{ name: 'moodle.zip', bytes: zip }, { name: 'cyki_LATE_777_1_handin.json', bytes: json(handIn('Cy Ki', 'c3')) }],
      text: handInToCode(handIn('Ada Lovelace', 'm1', '2026-01-11T10:00:00.000Z')), // Ada again, later, by mail
    });
    if (!view.ok) throw new Error(view.problems.join(' '));
    const moodle = moodleWorksheet(view.gradebook);
    expect(moodle.cells.slice(1).map((c) => [c[0], c[1]])).toEqual([['Participant 100002', 'Bo Berg'], ['Participant 100001', 'Ada Lovelace']]);
    expect(moodle.left.map((l) => [l.row.name, l.why])).toEqual([['Cy Ki', 'no-id']]);
    const canvas = canvasImport(view.gradebook);
    expect(canvas.cells.slice(2).map((c) => [c[0], c[1]])).toEqual([['Cy Ki', '777']]);
    expect(canvas.left).toHaveLength(2);
  });
});
