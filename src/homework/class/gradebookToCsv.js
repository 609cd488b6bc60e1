// @ts-check
// The gradebook as CSV, for a spreadsheet or a script: UTF-8 with a byte-order mark (without it
// Excel reads the file as the system's code page and Zoë becomes ZoÃ«), CRLF line ends and RFC 4180
// quoting (a field with a comma, a quote or a line break is quoted, its quotes doubled; one with a
// semicolon too, so a reader that guesses the separator, as Canvas's import does, guesses right).
// A column per question (1 right, 0 wrong, blank unanswered), the score as points and as a
// percentage, the student's name and id in the LMS where the hand-in's path gives them. The files
// an LMS imports are lmsGrades.js.
//
// A spreadsheet set to German, French or most other languages that write 87,5 reads a CSV with its
// list separator, a semicolon, and its decimal comma: the comma file opens there in one column.
// The semicolon form is for those: semicolons between cells, 87,5, and the time a hand-in was made
// as a date and time such a spreadsheet reads (2026-01-15 10:00, in this computer's time zone)
// where the comma form keeps the hand-in's own ISO 8601 time in UTC.
//
// Text from hand-ins (a name, a path) may start like a formula: a cell that starts with
// = + - @, a tab or a carriage return gets a leading apostrophe, as OWASP advises against CSV
// injection, so a spreadsheet shows it as text instead of running it (full-width ＝ ＋ － ＠ too,
// which some spreadsheets read as formulas).

// The column headings are the catalogue's, in the page's language; the cells stay machine-readable
// (1 and 0, yes and no, flags' ids, ISO 8601 times), so a script reads every language's file alike.
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/**
 * @typedef {import('./buildGradebook.js').Gradebook} Gradebook
 * @typedef {import('./buildGradebook.js').Row} Row
 */

const t = messages('class', english);

const FORMULA_START = /^[=+\-@\t\r\uff1d\uff0b\uff0d\uff20]/;
const BOM = '\ufeff';

/** Text from outside as a cell: a leading apostrophe where it would start a formula. */
export const textCell = (/** @type {string} */ text) => (FORMULA_START.test(text) ? `'${text}` : text);

/** @type {Record<import('./buildGradebook.js').Mark, string>} */
const mark = { right: '1', wrong: '0', unanswered: '' };

const pad = (/** @type {number} */ n) => String(n).padStart(2, '0');

/**
 * A hand-in's time as a spreadsheet in any language reads a date: 2026-01-15 10:00, local time; other text as it is.
 * @param {string} time
 */
export function localTime(time) {
  const date = new Date(time);
  if (!/^\d{4}-\d\d-\d\dT/.test(time) || Number.isNaN(date.getTime())) return textCell(time);
  return `${date.getFullYear()}-${pad(date.getMonth() + 1)}-${pad(date.getDate())} ${pad(date.getHours())}:${pad(date.getMinutes())}`;
}

/**
 * The gradebook's cells: a header row, then a row per hand-in that counts (and, with
 * includeSuperseded, those that do not, marked in the Counted column). Every cell is text.
 * decimalComma: 87,5 and local times, for the semicolon form.
 * @param {Gradebook} gradebook
 * @param {{ rows?: Row[], includeSuperseded?: boolean, decimalComma?: boolean }} [options] rows: in the order shown (sortRows)
 * @returns {string[][]}
 */
export function gradebookCells(gradebook, { rows = gradebook.rows, includeSuperseded = false, decimalComma = false } = {}) {
  const questions = gradebook.items.map((item, i) => t('csv.question', { number: i + 1, question: item.question }));
  const header = [
    ...['name', 'lmsName', 'lmsId', 'seed', 'score', 'outOf', 'percent'].map((key) => t(`csv.${key}`)), ...questions, t('csv.tries'),
    t(decimalComma ? 'csv.localTime' : 'csv.time'), t('csv.counted'), t('csv.flags'), t('csv.source'),
  ].map(textCell);
  const body = rows.filter((row) => includeSuperseded || row.counted).map((row) => [
    textCell(row.name), textCell(row.lmsName), row.lmsId, textCell(row.seed),
    String(row.score), String(row.total), decimalComma ? row.percent.toFixed(1).replace('.', ',') : row.percent.toFixed(1),
    ...row.marks.map((m) => mark[m]),
    row.triesTotal === null ? '' : String(row.triesTotal),
    decimalComma ? localTime(row.time ?? '') : textCell(row.time ?? ''), row.counted ? 'yes' : 'no',
    textCell(row.flags.map((f) => f.kind).join(' ')), textCell(row.source),
  ]);
  return [header, ...body];
}

/** A field as RFC 4180 writes it; in the comma form a semicolon is quoted too, in the semicolon form a comma is not (87,5 is a number). */
/** @type {(text: string, separator: string) => string} */
const field = (text, separator) => ((separator === ';' ? /[";\r\n]/ : /[",;\r\n]/).test(text) ? `"${text.replaceAll('"', '""')}"` : text);

/**
 * Cells as CSV text: byte-order mark, CRLF after every record, RFC 4180 quoting, cells apart by
 * `separator` (a comma; a semicolon for the semicolon form).
 * @param {string[][]} cells
 * @param {{ separator?: ',' | ';' }} [options]
 * @returns {string}
 */
export const cellsToCsv = (cells, { separator = ',' } = {}) => BOM
  + cells.map((row) => `${row.map((text) => field(text, separator)).join(separator)}\r\n`).join('');

/**
 * The gradebook as CSV text (gradebookCells, then cellsToCsv); the page saves it as a
 * text/csv;charset=utf-8 file. semicolons: the form for spreadsheets that write 87,5.
 * @param {Gradebook} gradebook
 * @param {{ rows?: Row[], includeSuperseded?: boolean, semicolons?: boolean }} [options]
 * @returns {string}
 */
export const gradebookToCsv = (gradebook, { semicolons = false, ...options } = {}) => cellsToCsv(
  gradebookCells(gradebook, { ...options, decimalComma: semicolons }), { separator: semicolons ? ';' : ',' });
