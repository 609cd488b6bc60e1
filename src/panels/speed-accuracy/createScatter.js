// The speed/accuracy scatter on a 2D canvas: cost on x (linear), worst display error on y
// (log, 8-bit codes), the Pareto front as a staircase, the budget as a horizontal line, each
// method labelled beside its point (nudged apart where they crowd), the recommended one ringed.
// Theme-aware (CSS variables read at draw time), sized for a projector, redrawn on resize.
import { cssVar, lineScale } from '../../ui/theme.js';
import { context2d } from '../../ui/context2d.js';
import { drawAxes, scatterFrame } from './scatterAxes.js';
import { drawPoints } from './scatterPoints.js';
import { drawLabels } from './scatterLabels.js';

/**
 * data: { points: [{ id, name, x, xMin, xMax, y, nan, recommended, passes }], front: [point index],
 * budget: { codes, label (the line's words) }, xLabel, yLabel, title, words: { front (the key), nan
 * (the band of NaN) } }: every word drawn comes in data. y is in 8-bit codes (0 is drawn at the floor).
 */
export function createScatter(container, { ariaLabel }) {
  const canvas = document.createElement('canvas');
  canvas.className = 'sa-chart';
  context2d(canvas); // claimed now, before the first run: see context2d.js
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', ariaLabel);
  container.append(canvas);
  let data = null;

  function draw() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(320, canvas.clientWidth);
    const height = Math.max(240, canvas.clientHeight);
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    const g = context2d(canvas);
    if (!g) return;
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = cssVar('--panel', '#161b22');
    g.fillRect(0, 0, width, height);
    if (!data) return;
    const colors = {
      text: cssVar('--text', '#eee'),
      grid: cssVar('--grid', 'rgba(255,255,255,0.14)'),
      budget: cssVar('--accent', '#ffd166'),
      front: cssVar('--c-exact', '#4cc9f0'),
      pass: cssVar('--c-green', '#5ee08a'),
      fail: cssVar('--c-red', '#ff6b6b'),
      labelBg: cssVar('--plot-label-bg', 'rgba(13,17,23,0.85)'),
    };
    const frame = scatterFrame(g, data, width, height, lineScale());
    drawAxes(g, frame, colors);
    const drawn = drawPoints(g, frame, colors);
    drawLabels(g, frame, colors, drawn);
  }

  const resize = new ResizeObserver(() => draw());
  resize.observe(canvas);
  const onTheme = () => draw();
  window.addEventListener('fresnel-lab:theme', onTheme);

  return {
    canvas,
    setData(next) {
      data = next;
      draw();
    },
    /** A PNG of the chart as drawn (the background is painted, so the file is not transparent). */
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      resize.disconnect();
      window.removeEventListener('fresnel-lab:theme', onTheme);
      canvas.remove();
    },
  };
}
