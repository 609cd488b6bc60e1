// The DOM of the stability panel: a note on what mediump really is here, the class legend, the
// two maps (GPU and JavaScript) each with its counts, and the probe readout.
import { el } from '../../ui/el.js';
import { CLASS_NAMES } from '../../optics/stabilityMap.js';
import { CLASS_COLORS } from './drawMap.js';

export const CLASS_LABELS = Object.freeze({
  fine: 'fine',
  aboveTolerance: 'error above tolerance',
  outOfRange: 'outside [0, 1]',
  notFinite: 'NaN or infinite',
});

function swatch(cls) {
  const s = el('span', 'st-swatch');
  s.style.background = `var(${CLASS_COLORS[CLASS_NAMES.indexOf(cls)]})`;
  return s;
}

function mapFigure(side) {
  const figure = el('figure', 'st-map');
  figure.dataset.side = side;
  const title = el('h3', 'st-map-title');
  const canvas = el('canvas', 'st-canvas');
  canvas.tabIndex = 0;
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
    name.append(swatch(cls), CLASS_LABELS[cls]);
    cells[cls] = el('td', '', '');
    cells[cls].dataset.count = cls;
    row.append(name, cells[cls]);
    body.append(row);
  }
  counts.append(body);
  const max = el('p', 'st-max');
  figure.append(title, canvas, message, counts, max);
  return {
    figure,
    canvas,
    setTitle(text, selected) {
      title.textContent = text;
      figure.classList.toggle('st-selected', selected);
    },
    setCounts(map) {
      for (const cls of CLASS_NAMES) cells[cls].textContent = map ? String(map.counts[cls]) : '–';
      max.textContent = map ? `largest finite |R − R_exact|: ${map.maxError.toPrecision(3)}` : '';
    },
    showMessage(text) {
      message.textContent = text;
      message.hidden = !text;
      canvas.hidden = Boolean(text);
    },
  };
}

export function buildStabilityDom(host) {
  const root = el('div', 'st-panel');
  const note = el('p', 'st-note');
  const legend = el('ul', 'st-legend');
  legend.setAttribute('aria-label', 'Map legend');
  for (const cls of CLASS_NAMES) {
    const item = el('li');
    item.append(swatch(cls), CLASS_LABELS[cls]);
    legend.append(item);
  }
  const critical = el('li');
  critical.append(el('span', 'st-line st-line-critical'), 'critical angle θc (total internal reflection to its right)');
  legend.append(critical);
  const maps = el('div', 'st-maps');
  const gpu = mapFigure('gpu');
  const js = mapFigure('js');
  maps.append(gpu.figure, js.figure);
  const readout = el('p', 'st-readout');
  readout.setAttribute('aria-live', 'polite');
  const hint = 'Hover a map, or focus it and use the arrow keys (Shift: 10 cells), to read θ, n_i/n_t, the value and the exact R.';
  root.append(note, legend, maps, readout);
  host.append(root);
  return {
    root,
    maps,
    gpu,
    js,
    setNote(text) { note.textContent = text; note.hidden = !text; },
    setReadout(text) { readout.textContent = text || hint; },
  };
}
