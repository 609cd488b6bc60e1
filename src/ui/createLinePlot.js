// A line plot for every panel: uPlot with theme-aware axes, large labels, a live cursor legend,
// and optional vertical markers with labels and a shaded range. Rebuilt on a theme change so line
// widths and colours follow it.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { cssVar, lineScale } from './theme.js';
import { quietestSpot } from './quietestSpot.js';
import { fixed, tickLabel } from './format.js';
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';

const t = messages('ui', english);

/** Colours may name a CSS custom property ('--c-exact') so they follow the theme. */
export function resolveColor(color) {
  return typeof color === 'string' && color.startsWith('--') ? cssVar(color) : color;
}

/**
 * Runs `make` with every 2D context it creates asked for with willReadFrequently, which keeps the
 * canvas on the CPU. uPlot makes its canvas and context inside its constructor and takes no context
 * attributes, hence the wrap. Why: a plot redraw is a few thick dashed polylines and some text,
 * which a CPU rasterizes in a millisecond or two; drawn through a software GPU (SwiftShader) Skia's
 * GPU path cost the hero about as much as its whole WebGL pass (npm run bench, bench/RESULTS.md).
 */
function withCpuCanvas(make) {
  const proto = HTMLCanvasElement.prototype;
  const { getContext } = proto;
  proto.getContext = function getCpuContext(type, attributes) {
    return getContext.call(this, type, type === '2d' ? { ...attributes, willReadFrequently: true } : attributes);
  };
  try {
    return make();
  } finally {
    proto.getContext = getContext;
  }
}

/** Below this width (a phone) an axis title keeps only what comes before its comma, and its unit. */
const COMPACT_PX = 480;
export function compactLabel(label) {
  const head = label.split(',')[0];
  const unit = t('plotDegrees'); // "(degrees)", as the panels' axis titles write it
  return head !== label && label.includes(unit) ? `${head} ${unit}` : head;
}

/** The type of tick labels and marker labels, `scale` × its CSS size (the canvas's pixel ratio). */
const tickFont = (scale = 1) => `${Math.round(15 * lineScale() * scale)}px system-ui, sans-serif`;

/** Width in CSS pixels of a tick label (measured unscaled: uPlot's context carries no transform). */
function textWidth(u, text) {
  u.ctx.save();
  u.ctx.font = tickFont();
  const width = u.ctx.measureText(String(text)).width;
  u.ctx.restore();
  return width;
}

function fmt(v, digits) {
  return v == null || Number.isNaN(v) ? '–' : fixed(v, digits);
}

/**
 * options: xLabel, xShort (the x title on a narrow plot; else compactLabel(xLabel)), yLabel,
 * xRange ([min, max] or null), yRange ([min, max] or null for auto), xUnit ('°' or ''), xStep (ticks
 * on multiples of it only, e.g. 1 for whole levels), series [{ label, stroke, width, dash }], height,
 * digits (legend decimals).
 * Markers set with setMarks([{ x, color, label, short, shadeTo }]) are drawn over the curves (short:
 * the label where the plot is too narrow for it), and the
 * audio trace's cursor with setCursor(x, label).
 */
export function createLinePlot(container, options) {
  const {
    xLabel, xShort = compactLabel(xLabel), yLabel, xRange = [0, 90], yRange = [0, 1], xUnit = '°', xStep = null,
    series, height = 320, digits = 4,
  } = options;
  let data = [[], ...series.map(() => [])];
  let marks = [];
  let cursor = null; // the audio trace's θ (createAudioTrace.js), drawn with the marks
  let plot = null;
  let compact = false;

  const axis = (label, unit, vertical = false) => ({
    label: compact && !vertical ? xShort : label,
    stroke: () => cssVar('--text'),
    font: tickFont(),
    labelFont: `bold ${Math.round(16 * lineScale())}px system-ui, sans-serif`,
    grid: { stroke: () => cssVar('--grid'), width: 1 },
    ticks: { stroke: () => cssVar('--grid') },
    values: (_u, ticks, _axis, _space, incr) => ticks.map((t) => `${tickLabel(t, incr)}${unit}`),
    // Room for the tick labels, which grow with the type in projector mode: their width (y axis)
    // grows in full, and more where the labels are long (0.0008), so they never reach the axis
    // title; the height of a line of text (x axis) grows less.
    size: vertical
      ? (u, values) => Math.max(Math.round(60 * lineScale()), 21 + Math.ceil(Math.max(0, ...(values ?? []).map((v) => textWidth(u, v)))))
      : Math.round(60 * Math.sqrt(lineScale())),
  });

  function build() {
    plot?.destroy();
    compact = container.clientWidth < COMPACT_PX;
    const scale = lineScale();
    plot = withCpuCanvas(() => new uPlot({
      width: Math.max(280, container.clientWidth),
      height,
      scales: { x: { time: false, range: xRange ?? undefined }, y: { range: yRange ?? undefined } },
      axes: [{ ...axis(xLabel, xUnit), ...(xStep ? { incrs: [1, 2, 5, 10].map((k) => k * xStep) } : {}) }, axis(yLabel, '', true)],
      series: [
        { label: (options.xShort ?? xLabel).split(',')[0], value: (_u, v) => (v == null ? '–' : `${fixed(v, 2)}${xUnit}`) },
        ...series.map((s) => ({
          label: s.label, stroke: resolveColor(s.stroke), dash: s.dash, width: (s.width ?? 2.5) * scale,
          value: (_u, v) => fmt(v, digits), points: { show: false },
        })),
      ],
      legend: { live: true },
      cursor: { drag: { x: false, y: false } },
      hooks: { draw: [(u) => drawMarks(u, cursor ? [...marks, cursor] : marks)] },
    }, data, container));
  }
  build();

  const resize = new ResizeObserver(() => {
    if ((container.clientWidth < COMPACT_PX) !== compact) build();
    else plot.setSize({ width: Math.max(280, container.clientWidth), height });
  });
  resize.observe(container);
  const onTheme = () => build();
  window.addEventListener('fresnel-lab:theme', onTheme);

  return {
    get plot() { return plot; },
    get data() { return data; },
    setData(next) {
      data = next;
      plot.setData(next);
    },
    setMarks(next) {
      marks = next.filter((m) => m && m.x != null && Number.isFinite(m.x));
      plot.redraw(false, false);
    },
    /** The audio trace's cursor at x (null: none), drawn over the curves in the text colour. */
    setCursor(x, label = '') {
      const next = x == null ? null : { x, color: '--text', label };
      if (next?.x === cursor?.x && next?.label === cursor?.label) return;
      cursor = next;
      plot.redraw(false, false);
    },
    /** The plot as a PNG data URL on the panel's background, with its legend drawn underneath
     *  (uPlot's legend is HTML, so a plain canvas copy would lose it). */
    toPng() {
      const source = plot.ctx.canvas;
      const ratio = window.devicePixelRatio || 1;
      const row = Math.round(30 * ratio);
      const out = document.createElement('canvas');
      out.width = source.width;
      out.height = source.height + row;
      const g = out.getContext('2d');
      g.fillStyle = cssVar('--panel', '#161b22');
      g.fillRect(0, 0, out.width, out.height);
      g.drawImage(source, 0, 0);
      g.font = `${Math.round(15 * ratio)}px system-ui, sans-serif`;
      g.textBaseline = 'middle';
      let x = plot.bbox.left;
      const y = source.height + row / 2;
      for (const s of series) {
        g.strokeStyle = resolveColor(s.stroke);
        g.lineWidth = 3 * ratio;
        g.setLineDash((s.dash ?? []).map((d) => d * ratio));
        g.beginPath();
        g.moveTo(x, y);
        g.lineTo(x + 24 * ratio, y);
        g.stroke();
        g.fillStyle = cssVar('--text', '#eee');
        g.fillText(s.label, x + 30 * ratio, y);
        x += 30 * ratio + g.measureText(s.label).width + 20 * ratio;
      }
      return out.toDataURL('image/png');
    },
    dispose() {
      window.removeEventListener('fresnel-lab:theme', onTheme);
      resize.disconnect();
      plot.destroy();
    },
  };
}

/**
 * Points along every shown curve in canvas pixels, no more than `spacing` apart (a steep segment
 * gets as many as its length on screen), for marker labels to keep off them (quietestSpot.js).
 */
function curvePixels(u, spacing) {
  const xs = u.data[0].map((v) => u.valToPos(v, 'x', true));
  const points = [];
  u.data.slice(1).forEach((ys, i) => {
    if (u.series[i + 1].show === false) return;
    let last = null;
    ys.forEach((y, j) => {
      if (y == null || Number.isNaN(y)) { last = null; return; }
      const p = [xs[j], u.valToPos(y, 'y', true)];
      if (last) {
        const steps = Math.ceil(Math.hypot(p[0] - last[0], p[1] - last[1]) / spacing);
        for (let k = 1; k < steps; k += 1) {
          points.push([last[0] + ((p[0] - last[0]) * k) / steps, last[1] + ((p[1] - last[1]) * k) / steps]);
        }
      }
      points.push(p);
      last = p;
    });
  });
  return points;
}

function drawMarks(u, marks) {
  const { ctx } = u;
  const { top, height, left, width } = u.bbox;
  const ratio = window.devicePixelRatio || 1;
  const px = (x) => Math.round(u.valToPos(x, 'x', true));
  ctx.save();
  ctx.font = tickFont(ratio);
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left'; // uPlot leaves its axis alignment on the context
  for (const m of marks) {
    if (m.shadeTo == null) continue;
    ctx.fillStyle = m.shade ?? 'rgba(239, 71, 111, 0.14)';
    const a = px(m.x);
    const b = px(m.shadeTo);
    ctx.fillRect(Math.min(a, b), top, Math.abs(b - a), height);
  }
  const points = curvePixels(u, 3 * ratio);
  const labelH = (19 * lineScale() + 2) * ratio;
  const step = 12 * ratio;
  const rows = Math.max(1, Math.floor((height - labelH - 12 * ratio) / step) + 1);
  const tops = Array.from({ length: rows }, (_, i) => top + 4 * ratio + i * step);
  const taken = [];
  // Every line first, then the labels over them, so no line runs through another mark's name.
  ctx.lineWidth = 2 * ratio * lineScale();
  ctx.setLineDash([6 * ratio, 5 * ratio]);
  for (const m of marks) {
    ctx.strokeStyle = resolveColor(m.color);
    ctx.beginPath();
    ctx.moveTo(px(m.x), top);
    ctx.lineTo(px(m.x), top + height);
    ctx.stroke();
  }
  marks.forEach((m) => {
    if (!m.label) return;
    const x = px(m.x);
    const color = resolveColor(m.color);
    // Beside its line at the height that hides the least (higher first, then right before left);
    // on a plot too narrow for either side, the short label (m.short), else kept inside the plot.
    const gap = 6 * ratio;
    const pad = 3 * ratio;
    const sides = (tw) => [x + gap, x - gap - tw].filter((tx) => tx >= left && tx + tw <= left + width);
    const text = m.short && !sides(ctx.measureText(m.label).width).length ? m.short : m.label;
    const w = ctx.measureText(text).width;
    const xs0 = sides(w);
    if (!xs0.length) xs0.push(Math.max(left + pad, left + width - w - pad));
    const spots = tops.flatMap((y0) => xs0.map((tx) => ({ x0: tx - pad, x1: tx + w + pad, y0, y1: y0 + labelH })));
    const spot = quietestSpot(spots, points, taken);
    taken.push({ ...spot, y0: spot.y0 - pad, y1: spot.y1 + pad });
    const tx = spot.x0 + pad;
    const ty = spot.y0 + 2 * ratio;
    ctx.fillStyle = cssVar('--plot-label-bg', 'rgba(13, 17, 23, 0.85)'); // legible over the curves
    ctx.fillRect(spot.x0, spot.y0, spot.x1 - spot.x0, labelH);
    ctx.fillStyle = color;
    ctx.fillText(text, tx, ty);
  });
  ctx.restore();
}
