// The DOM of the spheres panel: stage (canvas, labels, legend), readouts, plot host, toolbar.
// Plain elements with classes styled in src/styles.css; numbers use tabular figures so they
// update without the layout jumping.
import { button, el } from '../../ui/el.js';
import { angle as formatAngle, fixed } from '../../ui/format.js';
import { definitionList } from '../../ui/definitionList.js';
import english from 'virtual:messages/en/spheres';
import { messages } from '../../i18n/messages.js';

const t = messages('spheres', english);

// On a narrow screen the spheres are shown one at a time, at a size that reads, with these to switch
// (each mode's word in the catalogue).
const SINGLE = [['exact', 'exact'], ['schlick', 'schlick'], ['error', 'error']];

export function buildSpheresDom(host) {
  const root = el('div', 'spheres-panel');
  const main = el('div', 'panel-main');
  const stage = el('div', 'stage');
  const canvas = el('canvas', 'stage-canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvas'));
  const labels = el('div', 'stage-labels');
  const labelSpans = ['labelExact', 'labelSchlick', 'error'].map((word, i) => {
    const span = el('span', '', t(word));
    span.dataset.mode = SINGLE[i][0];
    return span;
  });
  labels.append(...labelSpans);
  const switcher = el('div', 'sphere-switch');
  switcher.setAttribute('role', 'group');
  switcher.setAttribute('aria-label', t('switcher'));
  switcher.hidden = true;
  const switches = SINGLE.map(([mode, word]) => {
    const b = button(t(word));
    b.dataset.mode = mode;
    switcher.append(b);
    return b;
  });
  const legend = el('div', 'legend');
  legend.setAttribute('aria-label', t('legend'));
  const legendBar = el('div', 'legend-bar');
  const legendTicks = el('div', 'legend-ticks');
  legend.append(legendBar, legendTicks);
  stage.append(canvas, labels, legend);

  const readout = el('p', 'readout');
  const summary = definitionList('summary');
  const plot = el('div', 'plot');
  plot.setAttribute('aria-label', t('plot'));
  main.append(switcher, stage, readout, summary.element, plot);
  root.append(main);
  host.append(root);

  const setReadout = (data) => {
    readout.textContent = data
      ? t('readout', {
        theta: formatAngle(data.theta), exact: fixed(data.exact, 4), schlick: fixed(data.schlick, 4), error: fixed(data.error, 4),
      })
      : t('readoutHint');
  };
  setReadout(null);

  return {
    stage,
    canvas,
    plot,
    setReadout,
    switches,
    /** One sphere ('exact' | 'schlick' | 'error') or all three (null): the stage, its labels and the switch follow. */
    setSingle(mode) {
      switcher.hidden = mode === null;
      stage.classList.toggle('stage-single', mode !== null);
      for (const b of switches) b.setAttribute('aria-pressed', String(b.dataset.mode === mode));
      for (const span of labelSpans) span.hidden = mode !== null && span.dataset.mode !== mode;
      legend.hidden = mode !== null && mode !== 'error';
    },
    setSummary(pairs) {
      summary.set(pairs);
    },
    setLegend(top, gradient) {
      legendBar.style.background = gradient;
      const digits = top < 0.01 ? 3 : top < 0.1 ? 3 : 2;
      const ticks = [0, top / 2, top].map((v) => fixed(v, digits));
      legendTicks.replaceChildren(...ticks.map((text, i) => el('span', '', i === 2 ? t('legendTop', { value: text }) : text)));
    },
  };
}
