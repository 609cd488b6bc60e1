// The DOM of the spheres panel: stage (canvas, labels, legend), readouts, plot host, toolbar.
// Plain elements with classes styled in src/styles.css; numbers use tabular figures so they
// update without the layout jumping.
import { button, el } from '../../ui/el.js';
import { angle as formatAngle, fixed } from '../../ui/format.js';
import { definitionList } from '../../ui/definitionList.js';

// On a narrow screen the spheres are shown one at a time, at a size that reads, with these to switch.
const SINGLE = [['exact', 'Exact'], ['schlick', 'Schlick'], ['error', '|Exact − Schlick|']];

export function buildSpheresDom(host) {
  const root = el('div', 'spheres-panel');
  const main = el('div', 'panel-main');
  const stage = el('div', 'stage');
  const canvas = el('canvas', 'stage-canvas');
  canvas.tabIndex = 0;
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label',
    'Three spheres: exact Fresnel, Schlick, and their difference as a heatmap. Drag or use the arrow keys to orbit.');
  const labels = el('div', 'stage-labels');
  const labelSpans = ['Exact Fresnel', "Schlick's approximation", '|Exact − Schlick|'].map((text, i) => {
    const span = el('span', '', text);
    span.dataset.mode = SINGLE[i][0];
    return span;
  });
  labels.append(...labelSpans);
  const switcher = el('div', 'sphere-switch');
  switcher.setAttribute('role', 'group');
  switcher.setAttribute('aria-label', 'Sphere shown');
  switcher.hidden = true;
  const switches = SINGLE.map(([mode, text]) => {
    const b = button(text);
    b.dataset.mode = mode;
    switcher.append(b);
    return b;
  });
  const legend = el('div', 'legend');
  legend.setAttribute('aria-label', 'Heatmap colour legend');
  const legendBar = el('div', 'legend-bar');
  const legendTicks = el('div', 'legend-ticks');
  legend.append(legendBar, legendTicks);
  stage.append(canvas, labels, legend);

  const readout = el('p', 'readout');
  const summary = definitionList('summary');
  const plot = el('div', 'plot');
  plot.setAttribute('aria-label', 'Reflectance R against angle θ');
  main.append(switcher, stage, readout, summary.element, plot);
  root.append(main);
  host.append(root);

  const setReadout = (data) => {
    readout.textContent = data
      ? `Pixel: θ = ${formatAngle(data.theta)}   F exact = ${fixed(data.exact, 4)}   F Schlick = ${fixed(data.schlick, 4)}   `
        + `|error| = ${fixed(data.error, 4)}`
      : 'Hover or tap a sphere to read θ, F exact, F Schlick and the error at that pixel.';
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
      legendTicks.replaceChildren(...ticks.map((text, i) => el('span', '', i === 2 ? `≥ ${text}` : text)));
    },
  };
}
