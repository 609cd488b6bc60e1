// The DOM of the spheres panel: stage (canvas, labels, legend), readouts, plot host, toolbar.
// Plain elements with classes styled in src/styles.css; numbers use tabular figures so they
// update without the layout jumping.
import { el } from '../../ui/el.js';
import { angle as formatAngle } from '../../ui/format.js';

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
  for (const text of ['Exact Fresnel', "Schlick's approximation", '|Exact − Schlick|']) labels.append(el('span', '', text));
  const legend = el('div', 'legend');
  legend.setAttribute('aria-label', 'Heatmap colour legend');
  const legendBar = el('div', 'legend-bar');
  const legendTicks = el('div', 'legend-ticks');
  legend.append(legendBar, legendTicks);
  stage.append(canvas, labels, legend);

  const readout = el('p', 'readout');
  const summary = el('dl', 'summary');
  const plot = el('div', 'plot');
  plot.setAttribute('aria-label', 'Reflectance R against angle θ');
  main.append(stage, readout, summary, plot);
  root.append(main);
  host.append(root);

  const setReadout = (data) => {
    readout.textContent = data
      ? `Pixel: θ = ${formatAngle(data.theta)}   F exact = ${data.exact.toFixed(4)}   F Schlick = ${data.schlick.toFixed(4)}   |error| = ${data.error.toFixed(4)}`
      : 'Hover a sphere to read θ, F exact, F Schlick and the error at that pixel.';
  };
  setReadout(null);

  return {
    stage,
    canvas,
    plot,
    setReadout,
    setSummary(pairs) {
      summary.replaceChildren(...pairs.flatMap(([term, value]) => {
        const wrap = el('div');
        wrap.append(el('dt', '', term), el('dd', '', value));
        return [wrap];
      }));
    },
    setLegend(top, gradient) {
      legendBar.style.background = gradient;
      const digits = top < 0.01 ? 3 : top < 0.1 ? 3 : 2;
      legendTicks.replaceChildren(...[0, top / 2, top].map((v, i) => el('span', '', i === 2 ? `≥ ${v.toFixed(digits)}` : v.toFixed(digits))));
    },
  };
}
