// @ts-check
// The class's gradebook as a table: a row per hand-in (one per student, with earlier hand-ins of the
// same student kept as rows that do not count), sortable by any column from its header button
// (aria-sort says how it is sorted), a mark per question, the flags a lecturer should look at, and
// a button that opens that student's report. It is a table to assistive technology (ARIA table
// roles) laid out as rows of one grid each, and a row out of view is not rendered
// (content-visibility): a <table> laid out and painted all its rows again as each slice arrived,
// seconds for a class of 500. Rows are made in slices, and sorting moves the rows that exist
// instead of making them again. Text only (textContent), never markup.
import { button, el } from '../../../ui/el.js';
import { pageLocale } from '../../../ui/safeLocale.js';
import { sortRows } from '../../class/sortRows.js';
import { kindName } from '../../questions.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../../i18n/messages.js';

const t = messages('class', english);

/** @typedef {import('../../class/buildGradebook.js').Row} Row */
/** @typedef {import('../../class/buildGradebook.js').Mark} Mark */
/** @typedef {import('../../class/sortRows.js').Column} Column */

/** @type {Record<Mark, string>} A mark's symbol, seen; its word (mark.<mark>) is heard. */
const MARKS = { right: '✓', wrong: '✗', unanswered: '–' };
/** The flags, in the order the legend says what they mean: flag.<kind> names one, flag.<kind>.meaning says it. */
const FLAG_KINDS = ['superseded', 'resubmitted', 'shared-seed', 'class-seed', 'copied', 'no-name'];
const flagName = (/** @type {string} */ kind) => (FLAG_KINDS.includes(kind) ? t(`flag.${kind}`) : kind);
const ROWS_PER_SLICE = 50;
const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/**
 * An element with an ARIA role: the table's parts are divs laid out as grids.
 * @param {string} role
 * @param {string | null} [className]
 * @param {string} [text]
 */
function part(role, className, text) {
  const node = el('div', className ?? undefined, text);
  node.setAttribute('role', role);
  return node;
}

/**
 * A cell whose symbol is seen and whose word is heard.
 * @param {Mark} mark
 */
function markCell(mark) {
  const cell = part('cell', `hw-mark hw-mark-${mark}`);
  const seen = el('span', null, MARKS[mark]);
  seen.setAttribute('aria-hidden', 'true');
  cell.append(seen, el('span', 'sr-only', t(`mark.${mark}`)));
  return cell;
}

// One formatter for every row (toLocaleString with options builds a formatter per call, the
// largest cost of making a row), made in the page's language when the first row is.
let dates = { locale: '', format: (/** @type {Date} */ _date) => '' };
const when = (/** @type {string | null} */ time) => {
  if (!time) return '—';
  if (dates.locale !== pageLocale()) {
    dates = { locale: pageLocale(), format: new Intl.DateTimeFormat(pageLocale(), { dateStyle: 'short', timeStyle: 'short' }).format };
  }
  return dates.format(new Date(time));
};
export const shownName = (/** @type {Row} */ row) => row.name || row.lmsName || t('table.noName');

/**
 * The table for `gradebook` (buildGradebook.js). onDetails(row): open that student's report.
 * Returns { element, ready: Promise (every row made), rowElement(key) }.
 * @param {import('../../class/buildGradebook.js').Gradebook} gradebook
 * @param {{ onDetails: (row: Row, from: HTMLElement) => void }} options
 */
export function createGradebookTable(gradebook, { onDetails }) {
  const wrap = el('div', 'hw-gradebook-wrap');
  // A wide table scrolls by itself; focusable so a keyboard can scroll it too.
  wrap.tabIndex = 0;
  wrap.setAttribute('role', 'region');
  wrap.setAttribute('aria-label', t('table.label'));
  const table = part('table', 'hw-gradebook');
  const caption = el('p', 'sr-only', t('table.caption', { title: gradebook.title }));
  caption.id = 'hw-gradebook-caption';
  table.setAttribute('aria-labelledby', caption.id);
  // Every row is a grid of the same columns (widths in classView.css), so a row lays out alone.
  table.style.setProperty('--hw-marks', String(gradebook.items.length));
  const headRow = part('row', 'hw-row hw-head');
  const head = part('rowgroup', 'hw-rowgroup');
  head.append(headRow);
  const body = part('rowgroup', 'hw-rowgroup hw-body');
  table.append(head, body);
  wrap.append(caption, table);

  /** @type {{ id: Column, text: string, title?: string }[]} */
  const columns = [
    .../** @type {const} */ (['name', 'seed', 'score', 'percent']).map((id) => ({ id, text: t(`table.${id}`) })),
    ...gradebook.items.map((item, i) => ({
      id: /** @type {const} */ (`item:${i}`),
      text: t('table.question', { number: i + 1 }),
      title: t('table.questionTitle', { kind: kindName(item.kind), question: item.question }),
    })),
    { id: 'tries', text: t('table.tries') }, { id: 'time', text: t('table.time') }, { id: 'flags', text: t('table.flags') },
  ];
  /** @type {Map<Column, HTMLElement>} */
  const headers = new Map();
  /** @type {{ column: Column | null, descending: boolean }} */
  let sorted = { column: null, descending: false };
  for (const column of columns) {
    const th = part('columnheader');
    const sort = button(column.text, 'hw-sort');
    if (column.title) sort.title = column.title;
    sort.setAttribute('aria-label', column.title ? t('table.sortTitled', { column: column.text, title: column.title })
      : t('table.sort', { column: column.text }));
    sort.addEventListener('click', () => sortBy(column.id));
    th.append(sort);
    headers.set(column.id, th);
    headRow.append(th);
  }
  headRow.append(part('columnheader', null, t('table.report')));

  /** @type {Map<number, HTMLElement>} row key → its row */
  const made = new Map();
  /** @param {Row} row */
  function makeRow(row) {
    const tr = part('row', `hw-row${row.counted ? '' : ' hw-superseded'}`);
    const name = part('rowheader', 'hw-name', shownName(row));
    if (!row.counted) name.append(el('span', 'hw-not-counted', ` ${t('table.notCounted')}`));
    tr.append(name, part('cell', 'hw-seed-cell', row.seed), part('cell', 'hw-num hw-points', `${row.score} / ${row.total}`),
      part('cell', 'hw-num', String(Math.round(row.percent))));
    for (const mark of row.marks) tr.append(markCell(mark));
    tr.append(part('cell', 'hw-num', row.triesTotal === null ? '—' : String(row.triesTotal)), part('cell', 'hw-time', when(row.time)));
    const flags = part('cell', 'hw-flags');
    for (const flag of row.flags) {
      const badge = el('span', `hw-flag hw-flag-${flag.kind}`, flagName(flag.kind));
      badge.title = flag.text;
      flags.append(badge);
    }
    const open = button(t('table.report'), 'hw-details');
    open.setAttribute('aria-label', t('table.reportOf', { name: shownName(row), counted: row.counted ? 'yes' : 'no' }));
    open.addEventListener('click', () => onDetails(row, open));
    const cell = part('cell');
    cell.append(open);
    tr.append(flags, cell);
    made.set(row.key, tr);
    return tr;
  }

  let order = gradebook.rows;
  /**
   * Sorts by `column`: again by the same column turns the order round; scores start highest first.
   * @param {Column} column
   */
  function sortBy(column) {
    sorted = { column, descending: sorted.column === column ? !sorted.descending : column === 'score' || column === 'percent' };
    applyOrder(column);
  }
  /** @param {Column} column */
  function applyOrder(column) {
    order = sortRows(gradebook.rows, column, { descending: sorted.descending, locale: document.documentElement.lang || undefined });
    for (const [id, th] of headers) {
      if (id === sorted.column) th.setAttribute('aria-sort', sorted.descending ? 'descending' : 'ascending');
      else th.removeAttribute('aria-sort');
    }
    body.append(...order.flatMap((row) => made.get(row.key) ?? []));
  }

  const ready = (async () => {
    for (let i = 0; i < gradebook.rows.length; i += ROWS_PER_SLICE) {
      await nextTask(); // each slice a task of its own, the first too: the page shows what it has
      const slice = gradebook.rows.slice(i, i + ROWS_PER_SLICE).map(makeRow);
      if (sorted.column) applyOrder(sorted.column); else body.append(...slice);
    }
  })();

  // The flags in this gradebook, each with what it means (a badge's title is seen only on hover).
  const element = el('div', 'hw-gradebook-block');
  element.append(wrap);
  const kinds = FLAG_KINDS.filter((kind) => gradebook.rows.some((row) => row.flags.some((f) => f.kind === kind)));
  if (kinds.length) {
    const legend = el('ul', 'hw-flag-legend');
    legend.setAttribute('aria-label', t('table.flagsMean'));
    for (const kind of kinds) {
      const item = el('li');
      item.append(el('span', `hw-flag hw-flag-${kind}`, flagName(kind)), ` ${t(`flag.${kind}.meaning`, gradebook.copiedRule)}`);
      legend.append(item);
    }
    element.append(legend);
  }

  return { element, ready, rowElement: (/** @type {number} */ key) => made.get(key), sortBy };
}
