// A stability map's figure (title and the chosen map's mark, canvas, a message in its place when
// there is none, the count of cells per class), as the stability panel and the shader lab show them;
// drawn by drawMap.js.
import { el } from '../../ui/el.js';
import { context2d } from '../../ui/context2d.js';
import { precise } from '../../ui/format.js';
import { CLASS_NAMES } from '../../methods/stabilityMap.js';
import { CLASS_COLORS } from './drawMap.js';
import { classLabel } from './classLabels.js';
import './stabilityMaps.css';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

export function swatch(cls) {
  const s = el('span', 'st-swatch');
  s.style.background = `var(${CLASS_COLORS[CLASS_NAMES.indexOf(cls)]})`;
  return s;
}

/** One map with its title, canvas, message (in place of the map) and counts per class. */
export function createMapFigure(side, { focusable = true } = {}) {
  const figure = el('figure', 'st-map');
  figure.dataset.side = side;
  const title = el('h3', 'st-map-title');
  // The chosen map's mark, beside its heading (whose text stays the map's name alone).
  const chosen = el('span', 'st-chosen');
  chosen.hidden = true;
  const head = el('div', 'st-map-head');
  head.append(title, chosen);
  const canvas = el('canvas', 'st-canvas');
  context2d(canvas); // claimed now, before the first map: see context2d.js
  canvas.tabIndex = focusable ? 0 : -1; // focusable where arrow keys move a probe over it
  canvas.setAttribute('role', 'img');
  const message = el('p', 'st-map-message');
  message.hidden = true;
  const counts = el('table', 'st-counts');
  const body = el('tbody');
  const cells = {};
  for (const cls of CLASS_NAMES) {
    const row = el('tr');
    const name = el('th', '');
    name.scope = 'row';
    name.append(swatch(cls), classLabel(cls));
    cells[cls] = el('td', '', '');
    cells[cls].dataset.count = cls;
    row.append(name, cells[cls]);
    body.append(row);
  }
  counts.append(body);
  const max = el('p', 'st-max');
  figure.append(head, canvas, message, counts, max);
  return {
    figure,
    canvas,
    setTitle(text, selected) {
      title.textContent = text;
      chosen.textContent = selected ? t('chosen') : '';
      chosen.hidden = !selected;
      figure.classList.toggle('st-selected', selected);
    },
    setCounts(map) {
      for (const cls of CLASS_NAMES) cells[cls].textContent = map ? String(map.counts[cls]) : '–';
      max.textContent = map ? t('largestError', { error: precise(map.maxError, 3) }) : '';
    },
    showMessage(text) {
      message.textContent = text;
      message.hidden = !text;
      canvas.hidden = Boolean(text);
    },
  };
}

