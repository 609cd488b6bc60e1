// The speed/accuracy scatter's frame and axes: where the plot box sits (room for the title, the
// key and a wrapped x title), the scales (cost linear on x, 8-bit codes in decades on y, a band
// for NaN above), then the grid, the tick labels, the axis titles and the chart's title.
import { sci, tickLabel } from '../../ui/format.js';

const FONT = 'system-ui, sans-serif';

/** Tick values for a linear axis over [lo, hi], about `count` of them at 1, 2 or 5 × 10^k, and their step. */
export function linearTicks(lo, hi, count = 6) {
  const raw = (hi - lo) / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((f) => f * mag).find((s) => raw <= s);
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return { ticks, step };
}

/** A cost tick: plain with the decimals its step needs, in powers of ten where it is very large or small. */
export function costTickLabel(v, step) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e4 || a < 1e-3 ? sci(v, 0) : tickLabel(v, step);
}

/** The label of the y axis's line at 10^e: 0.01 to 1000 written out, beyond that 1e−3, 1e4. */
export function powerLabel(e) {
  return e >= -2 && e <= 3 ? tickLabel(10 ** e, 10 ** e) : sci(10 ** e, 0);
}

/** Words of `text` in lines no wider than `maxWidth` at the context's font (a word wider stays whole). */
export function wrapText(g, text, maxWidth) {
  const lines = [];
  for (const word of text.split(' ')) {
    const last = lines.length - 1;
    if (last >= 0 && g.measureText(`${lines[last]} ${word}`).width <= maxWidth) lines[last] += ` ${word}`;
    else lines.push(word);
  }
  return lines;
}

/**
 * The layout of one drawing: plot box, rows above it, wrapped titles and the scales. s: line scale
 * (projector mode); `font(px, bold)` the canvas font at that scale.
 * @param {CanvasRenderingContext2D} g
 */
export function scatterFrame(g, data, width, height, s) {
  const font = (px, bold = false) => `${bold ? 'bold ' : ''}${Math.round(px * s)}px ${FONT}`;
  // On a wide chart the title sits right of the key in one row; on a narrow one (a phone) it
  // wraps onto rows of its own above the key, and the x title wraps below the ticks.
  const left = 92 * s;
  const right = width - 24;
  g.font = font(15, true);
  const keyWidth = (60 * s) + g.measureText(data.words.front).width; // the front's swatch and name, and a gap
  const titleBesideKey = !data.title || g.measureText(data.title).width + keyWidth <= right - left;
  const titleLines = titleBesideKey ? [] : wrapText(g, data.title, right - 8);
  const headerRows = titleLines.length + 1;
  g.font = font(16, true);
  const xLabelLines = wrapText(g, data.xLabel, width - 16);
  const box = { left, right, top: (24 + 20 * headerRows) * s, bottom: height - (40 + xLabelLines.length * 22) * s };

  // Axes ranges: x from 0 (or the lowest cost) to the highest max; y in decades around the data.
  const finite = data.points.filter((p) => !p.nan && Number.isFinite(p.x));
  const xs = finite.flatMap((p) => [p.x, p.xMin ?? p.x, p.xMax ?? p.x]);
  const xLo = Math.min(0, ...xs);
  const xHi = Math.max(...xs, xLo + 1e-9) * 1.08;
  const ys = finite.map((p) => p.y).filter((y) => y > 0);
  const yLoExp = Math.max(-6, Math.min(-1, Math.floor(Math.log10(Math.min(...ys, 0.1)))));
  const yHiExp = Math.max(1, Math.ceil(Math.log10(Math.max(...ys, data.budget.codes * 2, 1))));
  const hasNan = data.points.some((p) => p.nan);
  const nanBand = hasNan ? 34 * s : 0;
  const X = (v) => box.left + ((v - xLo) / (xHi - xLo)) * (box.right - box.left);
  const Y = (v) => {
    const e = Math.log10(Math.max(v, 10 ** yLoExp));
    return box.bottom - ((e - yLoExp) / (yHiExp - yLoExp)) * (box.bottom - box.top - nanBand);
  };
  return {
    data, width, height, s, font, box, titleBesideKey, titleLines, xLabelLines,
    keyY: box.top - 20 * s,
    rowH: 20 * s,
    xLo, xHi, yLoExp, yHiExp, hasNan, nanBand, X, Y,
    pointY: (p) => (p.nan ? box.top + nanBand / 2 : Y(p.y)),
  };
}

/**
 * Grid, ticks and tick labels, the plot's frame, the axis titles and the chart's title.
 * @param {CanvasRenderingContext2D} g
 */
export function drawAxes(g, frame, colors) {
  const { box, s, font, X, Y, data } = frame;
  g.lineWidth = 1;
  g.strokeStyle = colors.grid;
  g.fillStyle = colors.text;
  g.font = font(15);
  g.textAlign = 'right';
  g.textBaseline = 'middle';
  for (let e = frame.yLoExp; e <= frame.yHiExp; e += 1) {
    g.beginPath();
    g.moveTo(box.left, Y(10 ** e));
    g.lineTo(box.right, Y(10 ** e));
    g.stroke();
    g.fillText(powerLabel(e), box.left - 8, Y(10 ** e));
  }
  if (frame.hasNan) g.fillText(data.words.nan, box.left - 8, box.top + frame.nanBand / 2);
  g.textAlign = 'center';
  g.textBaseline = 'top';
  const { ticks, step } = linearTicks(frame.xLo, frame.xHi);
  for (const t of ticks) {
    g.beginPath();
    g.moveTo(X(t), box.top);
    g.lineTo(X(t), box.bottom);
    g.stroke();
    g.fillText(costTickLabel(t, step), X(t), box.bottom + 8);
  }
  g.strokeStyle = colors.text;
  g.lineWidth = 1.5 * s;
  g.strokeRect(box.left, box.top, box.right - box.left, box.bottom - box.top);
  g.font = font(16, true);
  frame.xLabelLines.forEach((line, i) => { // centred under the plot, shifted left as far as it must to stay whole
    const half = g.measureText(line).width / 2;
    const x = Math.max(half + 8, Math.min((box.left + box.right) / 2, frame.width - half - 8));
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
    g.fillStyle = colors.text;
    if (frame.titleBesideKey) {
      g.textAlign = 'right';
      g.fillText(data.title, box.right, frame.keyY);
    } else {
      g.textAlign = 'left';
      frame.titleLines.forEach((line, i) => g.fillText(line, 8, frame.keyY - (frame.titleLines.length - i) * frame.rowH));
    }
  }
}
