// The class's gradebook as a table: a row per hand-in (one per student, with earlier hand-ins of the
// same student kept as rows that do not count), sortable by any column from its header button
// (aria-sort says how it is sorted), a mark per question, the flags a lecturer should look at, and
// a button that opens that student's report. Rows are made in slices, so a class of 500 never
// holds the page's thread for long, and sorting moves the rows that exist instead of making them
// again. Text only (textContent), never markup.
import { button, el } from '../../../ui/el.js';
import { sortRows } from '../../class/sortRows.js';
import { KIND_NAMES } from '../../questions.js';

const MARKS = { right: ['✓', 'right'], wrong: ['✗', 'wrong'], unanswered: ['–', 'no answer'] };
const FLAG_NAMES = {
  superseded: 'not counted', resubmitted: 'handed in again', 'shared-seed': 'shared seed', 'class-seed': 'other seed',
  copied: 'same wrong answers', 'no-name': 'no name',
};
const ROWS_PER_SLICE = 60;
const nextTask = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/** A cell whose symbol is seen and whose word is heard. */
function markCell(mark) {
  const [symbol, word] = MARKS[mark];
  const cell = el('td', `hw-mark hw-mark-${mark}`);
  const seen = el('span', null, symbol);
  seen.setAttribute('aria-hidden', 'true');
  cell.append(seen, el('span', 'sr-only', word));
  return cell;
}

const when = (time) => (time ? new Date(time).toLocaleString(undefined, { dateStyle: 'short', timeStyle: 'short' }) : '—');
export const shownName = (row) => row.name || row.lmsName || '(no name)';

/**
 * The table for `gradebook` (buildGradebook.js). onDetails(row): open that student's report.
 * Returns { element, ready: Promise (every row made), rowElement(key) }.
 */
export function createGradebookTable(gradebook, { onDetails }) {
  const wrap = el('div', 'hw-gradebook-wrap');
  // A wide table scrolls by itself; focusable so a keyboard can scroll it too.
  wrap.tabIndex = 0;
  wrap.setAttribute('role', 'region');
  wrap.setAttribute('aria-label', 'Gradebook (scrolls sideways)');
  const table = el('table', 'hw-gradebook');
  table.append(el('caption', 'sr-only', `Gradebook of ${gradebook.title}: a row per hand-in; sort by any column with its header button.`));
  const headRow = el('tr');
  table.createTHead().append(headRow);
  const body = table.createTBody();
  wrap.append(table);

  const columns = [
    { id: 'name', text: 'Name' }, { id: 'seed', text: 'Seed' }, { id: 'score', text: 'Score' }, { id: 'percent', text: '%' },
    ...gradebook.items.map((item, i) => ({ id: `item:${i}`, text: `Q${i + 1}`, title: `${KIND_NAMES[item.kind] ?? item.kind}: ${item.question}` })),
    { id: 'tries', text: 'Tries' }, { id: 'time', text: 'Handed in' }, { id: 'flags', text: 'Flags' },
  ];
  const headers = new Map();
  let sorted = { column: null, descending: false };
  for (const column of columns) {
    const th = el('th');
    th.scope = 'col';
    const sort = button(column.text, 'hw-sort');
    if (column.title) sort.title = column.title;
    sort.setAttribute('aria-label', `${column.title ? `${column.text}, ${column.title}` : column.text}: sort`);
    sort.addEventListener('click', () => sortBy(column.id));
    th.append(sort);
    headers.set(column.id, th);
    headRow.append(th);
  }
  headRow.append(el('th', null, 'Report'));

  const made = new Map(); // row key → <tr>
  function makeRow(row) {
    const tr = el('tr', row.counted ? '' : 'hw-superseded');
    const name = el('th', null, shownName(row));
    name.scope = 'row';
    if (!row.counted) name.append(el('span', 'hw-not-counted', ' (not counted)'));
    tr.append(name, el('td', 'hw-seed-cell', row.seed), el('td', 'hw-num', `${row.score} / ${row.total}`), el('td', 'hw-num', String(Math.round(row.percent))));
    for (const mark of row.marks) tr.append(markCell(mark));
    tr.append(el('td', 'hw-num', row.triesTotal === null ? '—' : String(row.triesTotal)), el('td', null, when(row.time)));
    const flags = el('td', 'hw-flags');
    for (const flag of row.flags) {
      const badge = el('span', `hw-flag hw-flag-${flag.kind}`, FLAG_NAMES[flag.kind] ?? flag.kind);
      badge.title = flag.text;
      flags.append(badge);
    }
    const open = button('Report', 'hw-details');
    open.setAttribute('aria-label', `Report of ${shownName(row)}${row.counted ? '' : ' (not counted)'}`);
    open.addEventListener('click', () => onDetails(row, open));
    const cell = el('td');
    cell.append(open);
    tr.append(flags, cell);
    made.set(row.key, tr);
    return tr;
  }

  let order = gradebook.rows;
  /** Sorts by `column`: again by the same column turns the order round; scores start highest first. */
  function sortBy(column) {
    sorted = { column, descending: sorted.column === column ? !sorted.descending : column === 'score' || column === 'percent' };
    applyOrder();
  }
  function applyOrder() {
    order = sortRows(gradebook.rows, /** @type {any} */ (sorted.column), { descending: sorted.descending, locale: document.documentElement.lang || undefined });
    for (const [id, th] of headers) {
      if (id === sorted.column) th.setAttribute('aria-sort', sorted.descending ? 'descending' : 'ascending');
      else th.removeAttribute('aria-sort');
    }
    body.append(...order.map((row) => made.get(row.key)).filter(Boolean));
  }

  const ready = (async () => {
    for (let i = 0; i < gradebook.rows.length; i += ROWS_PER_SLICE) {
      const slice = gradebook.rows.slice(i, i + ROWS_PER_SLICE).map(makeRow);
      if (sorted.column) applyOrder(); else body.append(...slice);
      if (i + ROWS_PER_SLICE < gradebook.rows.length) await nextTask();
    }
  })();

  return { element: wrap, ready, rowElement: (key) => made.get(key), sortBy };
}
