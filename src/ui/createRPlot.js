// The live R(θ) plot: exact, Schlick, Rs, Rp and the error, with the Brewster and critical angles
// marked and an optional θ marker from the spheres. uPlot draws it; the numbers come from
// src/optics/curves.js. Sizes and line widths are chosen to read on a projector.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

const SERIES = [
  { label: 'Exact', stroke: '#4cc9f0', width: 3.5 },
  { label: 'Schlick', stroke: '#ffd166', width: 3.5, dash: [12, 6] },
  { label: 'Rs', stroke: '#ef476f', width: 2, dash: [3, 4] },
  { label: 'Rp', stroke: '#06d6a0', width: 2, dash: [10, 4, 3, 4] },
  { label: '|Exact − Schlick|', stroke: '#f4f4f4', width: 2.5 },
];

function fmt(v) {
  return v == null || Number.isNaN(v) ? '–' : v.toFixed(4);
}

export function createRPlot(container) {
  let marks = { brewster: null, critical: null, hover: null };
  const axisStyle = {
    stroke: '#e8e8e8',
    font: '16px system-ui, sans-serif',
    labelFont: 'bold 17px system-ui, sans-serif',
    grid: { stroke: 'rgba(255,255,255,0.12)', width: 1 },
    ticks: { stroke: 'rgba(255,255,255,0.3)' },
  };
  const opts = {
    width: Math.max(300, container.clientWidth),
    height: 340,
    scales: { x: { time: false, range: [0, 90] }, y: { range: [0, 1] } },
    axes: [
      { ...axisStyle, label: 'θ, angle from the normal (degrees)', values: (_u, ticks) => ticks.map((t) => `${t}°`) },
      { ...axisStyle, label: 'Reflectance R', size: 60 },
    ],
    series: [
      { label: 'θ', value: (_u, v) => (v == null ? '–' : `${v.toFixed(2)}°`) },
      ...SERIES.map((s) => ({ ...s, value: (_u, v) => fmt(v), points: { show: false } })),
    ],
    legend: { live: true },
    cursor: { drag: { x: false, y: false } },
    hooks: { draw: [(u) => drawMarks(u, marks)] },
  };
  const plot = new uPlot(opts, [[0, 90], [0, 0], [0, 0], [0, 0], [0, 0], [0, 0]], container);
  const resize = new ResizeObserver(() => plot.setSize({ width: Math.max(300, container.clientWidth), height: 340 }));
  resize.observe(container);
  return {
    plot,
    /** Replaces the curves; `landmarks` gives the Brewster and critical angles in degrees (or null). */
    setCurves(curves, landmarks) {
      marks = { ...marks, ...landmarks };
      plot.setData([curves.theta, curves.exact, curves.schlick, curves.s, curves.p, curves.error]);
    },
    /** Marks θ (degrees) from a hovered sphere pixel, or clears it with null. */
    setHover(theta) {
      marks = { ...marks, hover: theta };
      plot.redraw(false, false);
    },
    dispose() {
      resize.disconnect();
      plot.destroy();
    },
  };
}

function drawMarks(u, { brewster, critical, hover }) {
  const { ctx } = u;
  const { top, height, left, width } = u.bbox;
  const px = (deg) => Math.round(u.valToPos(deg, 'x', true));
  const ratio = devicePixelRatio || 1;
  ctx.save();
  ctx.font = `${Math.round(15 * ratio)}px system-ui, sans-serif`;
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left'; // uPlot leaves its axis alignment on the context
  if (critical != null) {
    // Past the critical angle no light is transmitted: shade that range.
    ctx.fillStyle = 'rgba(239, 71, 111, 0.12)';
    ctx.fillRect(px(critical), top, left + width - px(critical), height);
  }
  const vline = (deg, color, text, row) => {
    const x = px(deg);
    ctx.strokeStyle = color;
    ctx.lineWidth = 2 * ratio;
    ctx.setLineDash([6 * ratio, 5 * ratio]);
    ctx.beginPath();
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + height);
    ctx.stroke();
    const label = `${text} ${deg.toFixed(1)}°`;
    const w = ctx.measureText(label).width;
    const tx = x + 6 * ratio + w > left + width ? x - 6 * ratio - w : x + 6 * ratio;
    const ty = top + (6 + row * 22) * ratio;
    ctx.fillStyle = 'rgba(13, 17, 23, 0.85)'; // a backing so labels stay legible over the curves
    ctx.fillRect(tx - 3 * ratio, ty - 2 * ratio, w + 6 * ratio, 20 * ratio);
    ctx.fillStyle = color;
    ctx.fillText(label, tx, ty);
  };
  if (brewster != null) vline(brewster, '#06d6a0', 'Brewster', 0);
  if (critical != null) vline(critical, '#ef476f', 'Critical', 1);
  if (hover != null) vline(hover, '#ffffff', 'Pixel θ', 2);
  ctx.restore();
}
