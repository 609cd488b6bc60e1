// The DOM of the normal-mips panel: the stage (canvas with its two captions and the ground-truth
// sample counter), a line of key numbers, the mip-level legend of the overlay and the error table
// (RMSE per technique, overall and per mip-level band). Styles: styles.css (under .nm-panel).
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { colormapGradient } from '../../ui/colormap.js';
import { el } from '../../ui/el.js';
import { fixed } from '../../ui/format.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { techniqueName } from './techniqueName.js';

const t = messages('normal-mips', english);

const fmt = (x) => (Number.isFinite(x) ? fixed(x, 4) : '–');

let titles = 0; // ids for the error tables' titles (a page may mount the panel more than once)

export function buildNormalMipsDom(host) {
  const root = el('div', 'nm-panel');
  const stage = el('div', 'nm-stage');
  const canvas = el('canvas', 'nm-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvasLabel'));
  const leftCap = el('div', 'nm-cap nm-cap-left');
  const rightCap = el('div', 'nm-cap nm-cap-right');
  leftCap.hidden = true; // until setCaptions: an empty caption that fills in would grow in place
  rightCap.hidden = true;
  const busy = el('div', 'nm-busy');
  busy.setAttribute('role', 'status');
  busy.hidden = true;
  stage.append(canvas, leftCap, rightCap, busy);

  const summary = el('p', 'nm-summary');
  summary.setAttribute('aria-live', 'polite');
  const legend = el('div', 'nm-legend');
  const legendBar = el('span', 'nm-legend-bar');
  legendBar.style.background = colormapGradient();
  const legendLo = el('span', '', t('legendBottom', { level: '0' }));
  const legendHi = el('span', '');
  const legendLabel = el('span', 'nm-legend-label', t('legendLabel'));
  legend.append(legendLabel, legendLo, legendBar, legendHi);

  // The table's title sits outside its scrolling box, so it wraps to the column instead of
  // scrolling away with a wide table; aria-labelledby keeps it the table's name.
  const title = el('p', 'nm-errors-title', t('errorsTitle'));
  title.id = `nm-errors-title-${++titles}`;
  const table = el('table', 'nm-errors');
  table.setAttribute('aria-labelledby', title.id);
  const thead = el('thead');
  const tbody = el('tbody');
  table.append(thead, tbody);
  const shimmer = el('p', 'nm-shimmer');
  shimmer.setAttribute('aria-live', 'polite');
  const tableWrap = makeScrollBox(el('div', 'nm-table-wrap'), t('errorsBox'));
  tableWrap.append(table);
  const plotSlot = el('div', 'nm-plot-slot'); // the error-by-distance plot (createErrorDistancePlot.js)
  root.append(stage, summary, legend, title, tableWrap, plotSlot, shimmer);
  host.append(root);

  return {
    stage,
    root,
    canvas,
    plotSlot,
    setCaptions(left, right) {
      leftCap.textContent = left;
      rightCap.textContent = right;
      leftCap.hidden = !left;
      rightCap.hidden = !right;
    },
    /**
     * results: { technique: mean |Δ brightness| } or null (not measured for these settings, or measuring);
     * stopped: why a measurement ended without results.
     */
    setShimmer(results, measuring = false, stopped = '') {
      if (measuring) {
        shimmer.textContent = t('shimmer.measuring');
        return;
      }
      const list = () => Object.entries(results).sort((a, b) => a[1] - b[1])
        .map(([id, v]) => t('shimmer.item', { technique: techniqueName(id), value: fixed(v, 4) })).join(', ');
      shimmer.textContent = results ? t('shimmer.results', { list: list() }) : stopped || t('shimmer.idle');
    },
    /** A line over the stage while the chains build ('' hides it). */
    setBusy(text) {
      busy.textContent = text;
      busy.hidden = !text;
    },
    setSummary(text) {
      summary.textContent = text;
    },
    setLegend(hiText) {
      legendHi.textContent = hiText;
    },
    /** errors: { technique: bandedRmse result } or null while the truth converges; current is highlighted. */
    setErrors(errors, current, pendingText) {
      thead.replaceChildren();
      tbody.replaceChildren();
      if (!errors) {
        const row = el('tr');
        const cell = el('td', 'nm-pending', pendingText);
        row.append(cell);
        tbody.append(row);
        return;
      }
      const first = Object.values(errors)[0];
      const used = first.bands.filter((b) => Object.values(errors).some((e) => e.bands[b.level].count > 0));
      const head = el('tr');
      head.append(el('th', '', t('errors.technique')), el('th', '', t('errors.all')),
        ...used.map((b) => el('th', '', t('errors.band', { level: String(b.level) }))));
      thead.append(head);
      const order = Object.entries(errors).sort((a, b) => a[1].rmse - b[1].rmse);
      for (const [technique, e] of order) {
        const row = el('tr', technique === current ? 'nm-current' : '');
        row.dataset.technique = technique;
        const bands = used.map((b) => el('td', '', fmt(e.bands[b.level].rmse)));
        row.append(el('th', '', techniqueName(technique)), el('td', '', fmt(e.rmse)), ...bands);
        tbody.append(row);
      }
    },
  };
}
