// The speed/accuracy scatter on a 2D canvas: cost on x (linear), worst display error on y
// (log, 8-bit codes), the Pareto front as a staircase, the budget as a horizontal line, each
// method labelled beside its point (nudged apart where they crowd), the recommended one ringed.
// Theme-aware (CSS variables read at draw time), sized for a projector, redrawn on resize.
import { cssVar, lineScale } from '../../ui/theme.js';

const FONT = 'system-ui, sans-serif';

/** Tick values for a linear axis over [lo, hi], about `count` of them at 1, 2 or 5 × 10^k. */
function linearTicks(lo, hi, count = 6) {
  const raw = (hi - lo) / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((f) => f * mag).find((s) => raw <= s);
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return ticks;
}

function formatTick(v) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e4 || a < 1e-3 ? v.toExponential(0) : String(+v.toPrecision(3));
}

function formatPower(e) {
  if (e >= 0 && e <= 3) return String(10 ** e);
  if (e < 0 && e >= -2) return (10 ** e).toFixed(-e);
  return `1e${e}`;
}

/**
 * data: { points: [{ id, name, x, xMin, xMax, y, nan, recommended, passes }], front: [point index],
 * budget: { codes, label }, xLabel, yLabel, title }. y is in 8-bit codes (0 is drawn at the floor).
 */
export function createScatter(container, { ariaLabel }) {
  const canvas = document.createElement('canvas');
  canvas.className = 'sa-chart';
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
    const g = canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = cssVar('--panel', '#161b22');
    g.fillRect(0, 0, width, height);
    if (!data) return;
    const s = lineScale();
    const font = (px, bold = false) => `${bold ? 'bold ' : ''}${Math.round(px * s)}px ${FONT}`;
    const text = cssVar('--text', '#eee');
    const grid = cssVar('--grid', 'rgba(255,255,255,0.14)');
    const box = { left: 92 * s, right: width - 24, top: 44 * s, bottom: height - 64 * s };

    // Axes ranges: x from 0 (or the lowest cost) to the highest max; y in decades around the data.
    const { points } = data;
    const finite = points.filter((p) => !p.nan && Number.isFinite(p.x));
    const xs = finite.flatMap((p) => [p.x, p.xMin ?? p.x, p.xMax ?? p.x]);
    const xLo = Math.min(0, ...xs);
    const xHi = Math.max(...xs, xLo + 1e-9) * 1.08;
    const ys = finite.map((p) => p.y).filter((y) => y > 0);
    const yLoExp = Math.max(-6, Math.min(-1, Math.floor(Math.log10(Math.min(...ys, 0.1)))));
    const yHiExp = Math.max(1, Math.ceil(Math.log10(Math.max(...ys, data.budget.codes * 2, 1))));
    const hasNan = points.some((p) => p.nan);
    const nanBand = hasNan ? 34 * s : 0;
    const X = (v) => box.left + ((v - xLo) / (xHi - xLo)) * (box.right - box.left);
    const Y = (v) => {
      const e = Math.log10(Math.max(v, 10 ** yLoExp));
      return box.bottom - ((e - yLoExp) / (yHiExp - yLoExp)) * (box.bottom - box.top - nanBand);
    };
    const pointY = (p) => (p.nan ? box.top + nanBand / 2 : Y(p.y));

    // Grid, ticks and axis labels.
    g.lineWidth = 1;
    g.strokeStyle = grid;
    g.fillStyle = text;
    g.font = font(15);
    g.textAlign = 'right';
    g.textBaseline = 'middle';
    for (let e = yLoExp; e <= yHiExp; e += 1) {
      g.beginPath();
      g.moveTo(box.left, Y(10 ** e));
      g.lineTo(box.right, Y(10 ** e));
      g.stroke();
      g.fillText(formatPower(e), box.left - 8, Y(10 ** e));
    }
    if (hasNan) g.fillText('NaN', box.left - 8, box.top + nanBand / 2);
    g.textAlign = 'center';
    g.textBaseline = 'top';
    for (const t of linearTicks(xLo, xHi)) {
      g.beginPath();
      g.moveTo(X(t), box.top);
      g.lineTo(X(t), box.bottom);
      g.stroke();
      g.fillText(formatTick(t), X(t), box.bottom + 8);
    }
    g.strokeStyle = text;
    g.lineWidth = 1.5 * s;
    g.strokeRect(box.left, box.top, box.right - box.left, box.bottom - box.top);
    g.font = font(16, true);
    g.fillText(data.xLabel, (box.left + box.right) / 2, box.bottom + 34 * s);
    g.save();
    g.translate(22 * s, (box.top + box.bottom) / 2);
    g.rotate(-Math.PI / 2);
    g.textBaseline = 'middle';
    g.fillText(data.yLabel, 0, 0);
    g.restore();

    if (data.title) { // which scene and precision: the PNG export must say it without the page around it
      g.font = font(15, true);
      g.textAlign = 'right';
      g.textBaseline = 'middle';
      g.fillStyle = text;
      g.fillText(data.title, box.right, box.top - 20 * s);
    }

    // The budget line.
    const budgetColor = cssVar('--accent', '#ffd166');
    g.strokeStyle = budgetColor;
    g.lineWidth = 3 * s;
    g.setLineDash([10 * s, 6 * s]);
    g.beginPath();
    g.moveTo(box.left, Y(data.budget.codes));
    g.lineTo(box.right, Y(data.budget.codes));
    g.stroke();
    g.setLineDash([]);
    g.font = font(15, true);
    g.textAlign = 'left';
    g.textBaseline = 'bottom';
    g.fillStyle = budgetColor;
    g.fillText(`Budget: ${data.budget.label}`, box.left + 8, Y(data.budget.codes) - 4);

    // The Pareto front: a staircase through its points (right, then down).
    const frontColor = cssVar('--c-exact', '#4cc9f0');
    const front = data.front.map((i) => points[i]);
    if (front.length) {
      g.strokeStyle = frontColor;
      g.lineWidth = 2.5 * s;
      g.beginPath();
      g.moveTo(X(front[0].x), pointY(front[0]));
      front.forEach((p, i) => {
        const next = front[i + 1];
        g.lineTo(next ? X(next.x) : box.right, pointY(p));
        if (next) g.lineTo(X(next.x), pointY(next));
      });
      g.stroke();
      // Key above the plot: the front's colour and the budget's.
      g.font = font(15, true);
      g.textAlign = 'left';
      g.textBaseline = 'middle';
      const keyY = box.top - 20 * s;
      g.fillStyle = frontColor;
      g.fillRect(box.left, keyY - 1.5 * s, 28 * s, 3 * s);
      g.fillText('Pareto front', box.left + 36 * s, keyY);
    }

    // Spread bars and points first, then labels placed where they hide neither points nor labels.
    const pass = cssVar('--c-green', '#5ee08a');
    const fail = cssVar('--c-red', '#ff6b6b');
    const drawn = points.filter((p) => Number.isFinite(p.x)).map((p) => ({ p, px: X(p.x), py: pointY(p) }));
    for (const { p, px, py } of drawn) {
      const color = p.passes ? pass : fail;
      if (Number.isFinite(p.xMin) && Number.isFinite(p.xMax)) {
        g.strokeStyle = color;
        g.lineWidth = 2 * s;
        g.beginPath();
        for (const [x0, y0, x1, y1] of [[p.xMin, 0, p.xMax, 0], [p.xMin, -5, p.xMin, 5], [p.xMax, -5, p.xMax, 5]]) {
          g.moveTo(X(x0), py + y0 * s);
          g.lineTo(X(x1), py + y1 * s);
        }
        g.stroke();
      }
      g.beginPath();
      g.arc(px, py, 7 * s, 0, 2 * Math.PI);
      if (p.passes) {
        g.fillStyle = color; // filled: within the budget; hollow: over it (colour is not the only cue)
        g.fill();
      } else {
        g.strokeStyle = color;
        g.lineWidth = 3 * s;
        g.stroke();
      }
      if (p.recommended) {
        g.strokeStyle = budgetColor;
        g.lineWidth = 3 * s;
        g.beginPath();
        g.arc(px, py, 13 * s, 0, 2 * Math.PI);
        g.stroke();
      }
    }
    const lineH = 22 * s;
    const taken = drawn.map(({ px, py }) => ({ x0: px - 9 * s, x1: px + 9 * s, y0: py - 9 * s, y1: py + 9 * s }));
    g.font = font(15, true);
    g.textBaseline = 'middle';
    g.textAlign = 'left';
    for (const { p, px, py } of [...drawn].sort((a, b) => a.px - b.px)) {
      const label = p.recommended ? `${p.name} ★` : p.name;
      const w = g.measureText(label).width;
      const candidates = [];
      for (const k of [0, -1, 1, -2, 2, -3, 3, -4, 4]) {
        candidates.push({ x: px + 16 * s, y: py + k * lineH }, { x: px - 16 * s - w, y: py + k * lineH });
      }
      const fits = (c) => {
        const r = { x0: c.x - 3, x1: c.x + w + 3, y0: c.y - lineH / 2, y1: c.y + lineH / 2 };
        const inside = r.x0 >= box.left && r.x1 <= box.right && r.y0 >= box.top && r.y1 <= box.bottom;
        return inside && !taken.some((t) => r.x0 < t.x1 && t.x0 < r.x1 && r.y0 < t.y1 && t.y0 < r.y1) ? r : null;
      };
      let spot = candidates[0];
      let rect = null;
      for (const c of candidates) {
        rect = fits(c);
        if (rect) { spot = c; break; }
      }
      rect ??= { x0: spot.x - 3, x1: spot.x + w + 3, y0: spot.y - lineH / 2, y1: spot.y + lineH / 2 };
      taken.push(rect);
      if (Math.abs(spot.y - py) > 1) { // a leader line to a displaced label
        g.strokeStyle = text;
        g.lineWidth = 1.5 * s;
        g.beginPath();
        g.moveTo(px, py);
        g.lineTo(spot.x > px ? rect.x0 : rect.x1, spot.y);
        g.stroke();
      }
      g.fillStyle = cssVar('--plot-label-bg', 'rgba(13,17,23,0.85)');
      g.fillRect(rect.x0, rect.y0 + 1, rect.x1 - rect.x0, lineH - 2);
      g.fillStyle = text;
      g.fillText(label, spot.x, spot.y);
    }
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
