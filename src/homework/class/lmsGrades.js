// @ts-check
// Grades back into the LMS the hand-ins came from, as the file its grade import reads. Each
// student is found there by their id in that LMS, which only the hand-in's path gives (lmsName.js:
// the participant number in a Moodle download's folder names, the user id in a Canvas download's
// file names). A student who handed in more than once takes the id from any of their hand-ins (a
// later code pasted from a mail carries none). A student with no id, with two, or whose id is also
// another student's is left out of the file and listed, to be graded by hand.
//
// Moodle: the assignment's offline grading worksheet ("Offline grading worksheet" feedback type,
// https://docs.moodle.org/en/Assignment_settings#Feedback_types). Its importer
// (mod/assign/feedback/offline/importgradeslib.php) finds its columns by their headings, in the
// language Moodle is shown in, and needs three: "Identifier" ("Participant " and the participant
// number), "Grade" and "Last modified (grade)" (a grade changed in Moodle after that time is kept
// unless "Ignore last modified date" is ticked). The others are those of Moodle's own worksheet
// (mod/assign/gradingtable.php), for the lecturer's eye. A grade above the assignment's maximum is
// skipped by Moodle, so grades are given out of that maximum.
//
// Canvas: the gradebook's import CSV ("How do I import grades in the Gradebook?",
// https://community.canvaslms.com/t5/Instructor-Guide/How-do-I-import-grades-in-the-Gradebook/ta-p/807).
// Its importer (app/models/gradebook_importer.rb) reads the columns Student, ID, SIS User ID,
// SIS Login ID, Section, then one per assignment; a row whose first cell says "Points Possible"
// gives a new assignment its points. A student is found by ID (the Canvas user id) first.
import { textCell } from './gradebookToCsv.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/**
 * @typedef {import('./buildGradebook.js').Gradebook} Gradebook
 * @typedef {import('./buildGradebook.js').Row} Row
 * @typedef {{ row: Row, why: 'no-id' } | { row: Row, why: 'two-ids', ids: string[] }
 *   | { row: Row, why: 'shared-id', id: string, others: Row[] }} LeftOut
 * @typedef {{ cells: string[][], students: { id: string, row: Row }[], left: LeftOut[] }} LmsFile
 */

// The column headings below and "Participant " and "Points Possible" are the LMS's own words, which
// its importer looks for as they are (Moodle's in the language its pages are in, which the page
// asks to be English for the upload; Canvas's in English always): they are not translated, and stay
// out of the message catalogue. Only what the lab names itself (the Canvas column of a sheet without
// a title) is the catalogue's.
export const MOODLE_COLUMNS = Object.freeze(['Identifier', 'Full name', 'Grade', 'Maximum grade', 'Last modified (submission)',
  'Last modified (grade)']);
export const CANVAS_COLUMNS = Object.freeze(['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section']);
/** Moodle's "hiddenuser" string in English: the Identifier is it and the participant number. */
const PARTICIPANT = 'Participant ';
const t = messages('class', english);
const DEFAULT_OUT_OF = 100;

/** A grade as an LMS reads it: out of `outOf`, at most two decimals, a point for the decimal sign. */
/** @type {(row: Row, outOf: number) => string} */
const grade = (row, outOf) => String(Math.round((row.total ? (row.score / row.total) * outOf : 0) * 100) / 100);
/** @param {unknown} outOf */
const usable = (outOf) => (typeof outOf === 'number' && Number.isFinite(outOf) && outOf > 0 && outOf <= 1e6 ? outOf : DEFAULT_OUT_OF);
const nameOf = (/** @type {Row} */ row) => row.name || row.lmsName;

/**
 * The counted students with their one id in `lms`, and those left out with why.
 * @param {Gradebook} gradebook
 * @param {'moodle' | 'canvas'} lms
 * @returns {{ students: { id: string, row: Row }[], left: LeftOut[] }}
 */
export function lmsStudents(gradebook, lms) {
  const byKey = new Map(gradebook.rows.map((row) => [row.key, row]));
  /** @type {LeftOut[]} */
  const left = [];
  /** @type {{ id: string, row: Row }[]} */
  const found = [];
  for (const row of gradebook.rows.filter((r) => r.counted)) {
    const earlier = row.flags.filter((f) => f.kind === 'resubmitted').flatMap((f) => f.others).flatMap((key) => byKey.get(key) ?? []);
    const ids = [...new Set([row, ...earlier].filter((r) => r.lms === lms && r.lmsId).map((r) => r.lmsId))];
    if (!ids.length) left.push({ row, why: 'no-id' });
    else if (ids.length > 1) left.push({ row, why: 'two-ids', ids });
    else found.push({ id: ids[0], row });
  }
  /** @type {{ id: string, row: Row }[]} */
  const students = [];
  for (const entry of found) {
    const others = found.filter((f) => f.id === entry.id && f !== entry).map((f) => f.row);
    if (others.length) left.push({ row: entry.row, why: 'shared-id', id: entry.id, others });
    else students.push(entry);
  }
  left.sort((a, b) => a.row.key - b.row.key);
  return { students, left };
}

/**
 * Moodle's offline grading worksheet: a row per student with a participant number.
 * outOf: the assignment's maximum grade in Moodle (100); now: the time written as when the grade changed.
 * @param {Gradebook} gradebook
 * @param {{ outOf?: number, now?: Date }} [options]
 * @returns {LmsFile}
 */
export function moodleWorksheet(gradebook, { outOf, now = new Date() } = {}) {
  const max = usable(outOf);
  const { students, left } = lmsStudents(gradebook, 'moodle');
  const changed = now.toISOString(); // ISO 8601, which PHP's strtotime reads
  const cells = [[...MOODLE_COLUMNS], ...students.map(({ id, row }) => [
    `${PARTICIPANT}${id}`, textCell(nameOf(row)), grade(row, max), String(max), textCell(row.time ?? ''), changed,
  ])];
  return { cells, students, left };
}

/**
 * The heading of the assignment's column: the sheet's title, unless Canvas would read it as
 * something else ("Name (123)" is the assignment with id 123; "… Final Score" and the like are its
 * own read-only columns, dropped on import).
 * @param {unknown} title
 */
export function canvasColumn(title) {
  const text = String(title).trim().replace(/\((\d+)\)$/, '[$1]') || t('lms.canvasColumn');
  return /(Current|Final) (Score|Points|Grade)/.test(text) ? `${text} (Fresnel Lab)` : text;
}

/**
 * Canvas's gradebook import: a column for the sheet, its points, a row per student with a user id.
 * outOf: the assignment's points in Canvas (100).
 * @param {Gradebook} gradebook
 * @param {{ outOf?: number }} [options]
 * @returns {LmsFile}
 */
export function canvasImport(gradebook, { outOf } = {}) {
  const max = usable(outOf);
  const { students, left } = lmsStudents(gradebook, 'canvas');
  const cells = [
    [...CANVAS_COLUMNS, textCell(canvasColumn(gradebook.title))],
    ['Points Possible', '', '', '', '', String(max)],
    ...students.map(({ id, row }) => [textCell(nameOf(row)), id, '', '', '', grade(row, max)]),
  ];
  return { cells, students, left };
}
