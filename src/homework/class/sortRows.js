// @ts-check
// Sorting the gradebook by any column, as a table header does: stable (rows that tie keep their
// order, so sorting by score after name lists each score's students by name), names and sources in
// the reader's language's order (Zoë beside Zoe, "Student 9" before "Student 10"), scores and times
// as numbers. What is missing (no name, no time, an unanswered question, no tries) goes last in
// either direction, so the students who did answer are the ones at the top.
import { pageLocale, safeLocale } from '../../ui/safeLocale.js';

/**
 * @typedef {import('./buildGradebook.js').Row} Row
 * @typedef {'name' | 'lmsName' | 'seed' | 'score' | 'total' | 'percent' | 'tries' | 'time' | 'source' | 'flags' | 'counted'
 *   | `item:${number}`} Column
 */

const MARK_ORDER = { wrong: 0, right: 1 }; // ascending: who got it wrong first; unanswered last

/**
 * A row's value in a column: a number, a text, or null for missing.
 * @param {Row} row
 * @param {Column} column
 * @returns {number | string | null}
 */
function valueOf(row, column) {
  if (column === 'name' || column === 'lmsName' || column === 'seed' || column === 'source') return row[column] || null;
  if (column === 'score' || column === 'total' || column === 'percent') return row[column];
  if (column === 'tries') return row.triesTotal;
  if (column === 'time') return row.time === null ? null : Date.parse(row.time);
  if (column === 'flags') return row.flags.length;
  if (column === 'counted') return row.counted ? 1 : 0;
  const item = /^item:(\d+)$/.exec(column);
  if (item) {
    const mark = row.marks[Number(item[1])];
    return mark === undefined || mark === 'unanswered' ? null : MARK_ORDER[mark];
  }
  throw new RangeError(`There is no column ${column} to sort by.`);
}

/**
 * The rows sorted by `column` (a new list; the rows are not copied). locale: the collation's
 * language (the page's), default the reader's (pageLocale); a tag Intl would refuse gives English.
 * @param {Row[]} rows
 * @param {Column} column
 * @param {{ descending?: boolean, locale?: string | string[] }} [options]
 * @returns {Row[]}
 */
export function sortRows(rows, column, { descending = false, locale } = {}) {
  const collator = new Intl.Collator(safeLocale(locale ?? pageLocale()), { numeric: true, sensitivity: 'base' });
  const sign = descending ? -1 : 1;
  const decorated = rows.map((row, index) => ({ row, index, value: valueOf(row, column) }));
  decorated.sort((a, b) => {
    if (a.value === null || b.value === null) return Number(a.value === null) - Number(b.value === null) || a.index - b.index;
    // One column's values are all texts or all numbers.
    const order = typeof a.value === 'string' ? collator.compare(a.value, String(b.value)) : a.value - Number(b.value);
    return sign * order || a.index - b.index;
  });
  return decorated.map((d) => d.row);
}
