// The speed/accuracy scatter on a 2D canvas: cost on x (linear), worst display error on y
// (log, 8-bit codes), the Pareto front as a staircase, the budget as a horizontal line, each
// method labelled beside its point (nudged apart where they crowd), the recommended one ringed.
// Theme-aware (CSS variables read at draw time), sized for a projector, redrawn on resize.
import { cssVar, lineScale } from '../../ui/theme.js';
import { context2d } from '../../ui/context2d.js';

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

/** Words of `text` in lines no wider than `maxWidth` at the context's font (a word wider stays whole). */
function wrapText(g, text, maxWidth) {
  const lines = [];
  for (const word of text.split(' ')) {
    const last = lines.length - 1;
    if (last >= 0 && g.measureText(`${lines[last]} ${word}`).width <= maxWidth) lines[last] += ` ${word}`;
    else lines.push(word);
  }
  return lines;
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
    const s = lineScale();
    const font = (px, bold = false) => `${bold ? 'bold ' : ''}${Math.round(px * s)}px ${FONT}`;
    const text = cssVar('--text', '#eee');
    const grid = cssVar('--grid', 'rgba(255,255,255,0.14)');
    // On a wide chart the title sits right of the key in one row; on a narrow one (a phone) it
    // wraps onto rows of its own above the key, and the x title wraps below the ticks.
    const left = 92 * s;
    const right = width - 24;
    const keyWidth = 150 * s;
    g.font = font(15, true);
    const titleBesideKey = !data.title || g.measureText(data.title).width + keyWidth <= right - left;
    const titleLines = titleBesideKey ? [] : wrapText(g, data.title, right - 8);
    const headerRows = titleLines.length + 1;
    g.font = font(16, true);
    const xLabelLines = wrapText(g, data.xLabel, width - 16);
    const rowH = 20 * s;
    const box = { left, right, top: (24 + 20 * headerRows) * s, bottom: height - (40 + xLabelLines.length * 22) * s };
    const keyY = box.top - 20 * s;

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
    xLabelLines.forEach((line, i) => { // centred under the plot, shifted left as far as it must to stay whole
      const half = g.measureText(line).width / 2;
      const x = Math.max(half + 8, Math.min((box.left + box.right) / 2, width - half - 8));
      g.fillText(line, x, box.bottom + (34 + 22 * i) * s);
    });
    g.save();
    g.translate(22 * s, (box.top + box.bottom) / 2);
    g.rotate(-Math.PI / 2);
    g.textBaseline = 'middle';
    g.fillText(data.yLabel, 0, 0);
    g.restore();

    if (data.title) { // which scene and precision: the PNG export must say it without the page around it
      g.font = font(15, true);
      g.textBaseline = 'middle';
      g.fillStyle = text;
      if (titleBesideKey) {
        g.textAlign = 'right';
        g.fillText(data.title, box.right, keyY);
      } else {
        g.textAlign = 'left';
        titleLines.forEach((line, i) => g.fillText(line, 8, keyY - (titleLines.length - i) * rowH));
      }
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
    const budgetText = `Budget: ${data.budget.label}`; // drawn with the point labels, over their leaders
    const budgetRect = { x0: box.left + 4, x1: box.left + 12 + g.measureText(budgetText).width, y0: Y(data.budget.codes) - 4 - 18 * s, y1: Y(data.budget.codes) + 2 * s };

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
    // A point hidden costs far more than a label overlapped (weight), should no spot be free.
    const taken = [budgetRect, ...drawn.map(({ px, py }) => ({ x0: px - 9 * s, x1: px + 9 * s, y0: py - 9 * s, y1: py + 9 * s, weight: 50 }))];
    const placed = [];
    g.font = font(15, true);
    g.textBaseline = 'middle';
    g.textAlign = 'left';
    for (const { p, px, py } of [...drawn].sort((a, b) => a.px - b.px)) {
      const label = p.recommended ? `${p.name} ★` : p.name;
      const w = g.measureText(label).width;
      const candidates = [];
      for (const k of [0, -1, 1, -2, 2, -3, 3, -4, 4, -5, 5, -6, 6, -7, 7, -8, 8]) {
        candidates.push({ x: px + 16 * s, y: py + k * lineH }, { x: px - 16 * s - w, y: py + k * lineH });
      }
      // The first spot inside the plot that covers nothing; failing that (a crowded narrow chart),
      // the spot inside that covers the least.
      const rectAt = (c) => ({ x0: c.x - 3, x1: c.x + w + 3, y0: c.y - lineH / 2, y1: c.y + lineH / 2 });
      const inside = (r) => r.x0 >= box.left && r.x1 <= box.right && r.y0 >= box.top && r.y1 <= box.bottom;
      const covered = (r) => taken.reduce((sum, t) => sum + (t.weight ?? 1)
        * Math.max(0, Math.min(r.x1, t.x1) - Math.max(r.x0, t.x0)) * Math.max(0, Math.min(r.y1, t.y1) - Math.max(r.y0, t.y0)), 0);
      const inBox = candidates.filter((c) => inside(rectAt(c)));
      const spot = inBox.find((c) => covered(rectAt(c)) === 0)
        ?? inBox.reduce((best, c) => (best && covered(rectAt(best)) <= covered(rectAt(c)) ? best : c), null)
        ?? candidates[0];
      const rect = rectAt(spot);
      taken.push(rect);
      placed.push({ label, px, py, spot, rect });
    }
    // Leader lines to displaced labels first, then every label on its background over them, so no
    // line runs through a name.
    g.strokeStyle = text;
    g.lineWidth = 1.5 * s;
    for (const { px, py, spot, rect } of placed) {
      if (Math.abs(spot.y - py) <= 1) continue;
      g.beginPath();
      g.moveTo(px, py);
      g.lineTo(spot.x > px ? rect.x0 : rect.x1, spot.y);
      g.stroke();
    }
    const labelBg = cssVar('--plot-label-bg', 'rgba(13,17,23,0.85)');
    g.fillStyle = labelBg;
    g.fillRect(budgetRect.x0, budgetRect.y0, budgetRect.x1 - budgetRect.x0, budgetRect.y1 - budgetRect.y0 - 4 * s);
    g.fillStyle = budgetColor;
    g.textBaseline = 'bottom';
    g.fillText(budgetText, box.left + 8, Y(data.budget.codes) - 4);
    g.textBaseline = 'middle';
    for (const { label, spot, rect } of placed) {
      g.fillStyle = labelBg;
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
