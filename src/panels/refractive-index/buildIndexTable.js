// The table of the refractive-index panel: sort buttons in the header cells (with aria-sort), one
// "Use" button per row, and the custom row in the footer. Rebuilt from data on every render, so the
// DOM never disagrees with the values.
import { el } from '../../ui/el.js';
import { angle, fixed, grouped, rounded } from '../../ui/format.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { optionLabel } from '../controlText.js';
import english from 'virtual:messages/en/refractive-index';
import { messages } from '../../i18n/messages.js';

const t = messages('refractive-index', english);

/**
 * The table's columns, each a sort key of materialRows.js (SORT_KEYS). A heading is the name of its
 * option in the "Sort by" control (the catalogue's controls.refractive-index.sort.<key>): one name each.
 */
export const COLUMNS = [
  { key: 'name' },
  { key: 'n', numeric: true },
  { key: 'speed', numeric: true },
  { key: 'r0', numeric: true },
  { key: 'critical', numeric: true },
  { key: 'source' },
];

/** n with at least four decimals, and all the data has (air: 1.000293), in the page's language (es: 1,3333). */
export function formatIndex(n) {
  const text = String(rounded(n, 6));
  const decimals = text.includes('.') ? text.split('.')[1].length : 0;
  return fixed(n, Math.max(4, decimals));
}

/**
 * 224850.3 → "224 850" (grouped, SI style), rounded to `step` km/s: the data's n, to 4 or 5
 * decimals, holds a phase speed to about 10 km/s; a group speed from three wavelengths, to about 1000.
 */
export function formatKmS(value, step = 10) {
  return grouped(Math.round(value / step) * step);
}

/** Long paths may wrap after each '/' and inside the site name (a zero-width space), so the column stays narrow. */
function breakable(text) {
  return text.replaceAll('/', '/\u200b').replaceAll('refractiveindex.', 'refractiveindex.\u200b');
}

function cells(row) {
  return [
    formatIndex(row.n),
    t('speed', { value: fixed(row.speed, 4) }),
    fixed(row.r0, 3),
    row.critical === null ? t('noCritical') : angle(row.critical, 1),
  ];
}

export function buildIndexTable(host, { onSort, onUse }) {
  const root = el('div', 'ri-panel');
  const scroller = makeScrollBox(el('div', 'ri-scroll'), t('table'));
  const table = el('table', 'ri-table');
  const caption = el('caption', 'ri-caption', t('caption'));
  const thead = el('thead');
  const tbody = el('tbody');
  const tfoot = el('tfoot');
  table.append(caption, thead, tbody, tfoot);
  scroller.append(table);
  root.append(scroller);
  host.append(root);

  const headRow = el('tr');
  const headers = {};
  for (const column of COLUMNS) {
    const th = el('th');
    th.scope = 'col';
    if (column.numeric) th.classList.add('ri-num');
    const button = el('button', 'ri-sort');
    button.type = 'button';
    button.dataset.sort = column.key;
    button.append(el('span', '', optionLabel('refractive-index', 'sort', column.key)), el('span', 'ri-sort-mark'));
    button.addEventListener('click', () => onSort(column.key));
    th.append(button);
    headers[column.key] = { th, button };
    headRow.append(th);
  }
  // The Apply column comes second, so it stays on screen when a narrow table scrolls sideways.
  const useTh = el('th', '', t('apply'));
  useTh.scope = 'col';
  headRow.insertBefore(useTh, headers.n.th);
  thead.append(headRow);

  function rowElement(row, selected) {
    const tr = el('tr', row.id === 'custom' ? 'ri-custom' : '');
    tr.dataset.id = row.id;
    const isSelected = row.id === selected;
    if (isSelected) {
      tr.classList.add('ri-selected');
      tr.setAttribute('aria-current', 'true');
    }
    const name = el('th', 'ri-name', row.name);
    name.scope = 'row';
    const [n, speed, r0, critical] = cells(row);
    const speedCell = el('td', 'ri-num');
    speedCell.append(el('span', '', speed), el('span', 'ri-kms', t('speedKmS', { value: formatKmS(row.speedKmS) })));
    if (row.groupSpeedKmS !== null) {
      speedCell.append(el('span', 'ri-kms ri-group', t('pulse', { value: formatKmS(row.groupSpeedKmS, 1000) })));
    }
    const useCell = el('td');
    tr.append(name, useCell, el('td', 'ri-num ri-n', n), speedCell, el('td', 'ri-num ri-r0', r0),
      el('td', 'ri-num ri-critical', critical), el('td', 'ri-source', breakable(row.source)));
    const use = el('button', 'ri-use', isSelected ? t('inUse') : t('use'));
    use.type = 'button';
    use.setAttribute('aria-pressed', String(isSelected));
    use.setAttribute('aria-label', t('useLabel', { name: row.name, n: formatIndex(row.n) }));
    use.addEventListener('click', () => onUse(row));
    useCell.append(use);
    return tr;
  }

  return {
    table,
    /** rows: sorted materials; custom: the custom row; state: { sort, dir, selected }. */
    render(rows, custom, { sort, dir, selected }) {
      for (const [key, { th }] of Object.entries(headers)) {
        const active = key === sort;
        th.setAttribute('aria-sort', active ? (dir === 'asc' ? 'ascending' : 'descending') : 'none');
        th.querySelector('.ri-sort-mark').textContent = active ? (dir === 'asc' ? ' ▲' : ' ▼') : ' ↕';
      }
      // Keep keyboard focus on the same button across the rebuild.
      const focused = root.contains(document.activeElement) ? document.activeElement : null;
      const focusRow = focused?.closest('tr')?.dataset.id;
      tbody.replaceChildren(...rows.map((row) => rowElement(row, selected)));
      tfoot.replaceChildren(rowElement(custom, selected));
      if (focused?.classList.contains('ri-use')) root.querySelector(`tr[data-id="${focusRow}"] .ri-use`)?.focus();
      else if (focused?.classList.contains('ri-sort')) headers[focused.dataset.sort]?.button.focus();
    },
    dispose() {
      root.remove();
    },
  };
}
