// @ts-check
// The gradebook as CSV, for a spreadsheet or a script: UTF-8 with a byte-order mark (without it
// Excel reads the file as the system's code page and Zoë becomes ZoÃ«), CRLF line ends and RFC 4180
// quoting (a field with a comma, a quote or a line break is quoted, its quotes doubled; one with a
// semicolon too, so a reader that guesses the separator, as Canvas's import does, guesses right).
// A column per question (1 right, 0 wrong, blank unanswered), the score as points and as a
// percentage, the student's name and id in the LMS where the hand-in's path gives them. The files
// an LMS imports are lmsGrades.js. Text from hand-ins (a name, a path) may start like a formula: a cell that starts with
// = + - @, a tab or a carriage return gets a leading apostrophe, as OWASP advises against CSV
// injection, so a spreadsheet shows it as text instead of running it (full-width ＝ ＋ － ＠ too,
// which some spreadsheets read as formulas).

/**
 * @typedef {import('./buildGradebook.js').Gradebook} Gradebook
 * @typedef {import('./buildGradebook.js').Row} Row
 */

const FORMULA_START = /^[=+\-@\t\r\uff1d\uff0b\uff0d\uff20]/;
const BOM = '\ufeff';

/** Text from outside as a cell: a leading apostrophe where it would start a formula. */
export const textCell = (text) => (FORMULA_START.test(text) ? `'${text}` : text);

const mark = { right: '1', wrong: '0', unanswered: '' };

/**
 * The gradebook's cells: a header row, then a row per hand-in that counts (and, with
 * includeSuperseded, those that do not, marked in the Counted column). Every cell is text.
 * @param {Gradebook} gradebook
 * @param {{ rows?: Row[], includeSuperseded?: boolean }} [options] rows: in the order shown (sortRows)
 * @returns {string[][]}
 */
export function gradebookCells(gradebook, { rows = gradebook.rows, includeSuperseded = false } = {}) {
  const questions = gradebook.items.map((item, i) => `Q${i + 1} ${item.question}`);
  const header = [
    'Name', 'LMS name', 'LMS user id', 'Seed', 'Score', 'Out of', 'Percent', ...questions, 'Tries', 'Handed in', 'Counted', 'Flags',
    'Source',
  ];
  const body = rows.filter((row) => includeSuperseded || row.counted).map((row) => [
    textCell(row.name), textCell(row.lmsName), row.lmsId, textCell(row.seed),
    String(row.score), String(row.total), row.percent.toFixed(1),
    ...row.marks.map((m) => mark[m]),
    row.triesTotal === null ? '' : String(row.triesTotal),
    textCell(row.time ?? ''), row.counted ? 'yes' : 'no',
    textCell(row.flags.map((f) => f.kind).join(' ')), textCell(row.source),
  ]);
  return [header, ...body];
}

/** A field as RFC 4180 writes it. */
const field = (text) => (/[",;\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text);

/**
 * Cells as CSV text: byte-order mark, CRLF after every record, RFC 4180 quoting.
 * @param {string[][]} cells
 * @returns {string}
 */
export const cellsToCsv = (cells) => BOM + cells.map((row) => `${row.map(field).join(',')}\r\n`).join('');

/**
 * The gradebook as CSV text (gradebookCells, then cellsToCsv); the page saves it as a
 * text/csv;charset=utf-8 file.
 * @param {Gradebook} gradebook
 * @param {{ rows?: Row[], includeSuperseded?: boolean }} [options]
 * @returns {string}
 */
export const gradebookToCsv = (gradebook, options) => cellsToCsv(gradebookCells(gradebook, options));
