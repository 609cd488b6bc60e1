// Draws one stability map on a 2D canvas: the class of every cell (θ across, n_i/n_t up, both
// linear), axes, the critical-angle curve θc = asin(1/ratio) for ratio > 1, rings around failures
// when they are few (one failing cell would otherwise be a 3-pixel dot on a projector), and the probed
// cell. Colours come from the theme's CSS variables.
import { cssVar, lineScale } from '../../ui/theme.js';
import { context2d } from '../../ui/context2d.js';
import { fixed } from '../../ui/format.js';
import { criticalAngleDeg } from '../../methods/classifyGrid.js';
import { FINE } from '../../methods/stabilityMap.js';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

/** Class index → theme colour: fine is a quiet neutral so every failure stands out. */
export const CLASS_COLORS = Object.freeze(['--border', '--c-schlick', '--c-error', '--c-red']);
const RING_LIMIT = 200; // at most this many failing cells get a ring each

// Any CSS colour → [r, g, b] through a 1×1 canvas (the theme may use hex, rgb() or color-mix()).
const probe = typeof document === 'undefined' ? null : document.createElement('canvas').getContext('2d', { willReadFrequently: true });
function rgb(css) {
  probe.clearRect(0, 0, 1, 1);
  probe.fillStyle = '#000';
  probe.fillStyle = css;
  probe.fillRect(0, 0, 1, 1);
  return [...probe.getImageData(0, 0, 1, 1).data.slice(0, 3)];
}

/** Plot-area geometry in CSS pixels and the cell ↔ pixel maps for a map's grid. */
export function layout(cssWidth, cssHeight, map, fontPx) {
  const pad = {
    left: Math.round(fontPx * 3.6), right: Math.round(fontPx * 0.9), top: Math.round(fontPx * 0.8), bottom: Math.round(fontPx * 3),
  };
  const plot = {
    x: pad.left, y: pad.top, w: Math.max(10, cssWidth - pad.left - pad.right), h: Math.max(10, cssHeight - pad.top - pad.bottom),
  };
  const dTheta = (map.thetaDeg[map.width - 1] - map.thetaDeg[0]) / (map.width - 1);
  const dRatio = (map.ratio[map.height - 1] - map.ratio[0]) / (map.height - 1);
  const t0 = map.thetaDeg[0] - dTheta / 2;
  const t1 = map.thetaDeg[map.width - 1] + dTheta / 2;
  const r0 = map.ratio[0] - dRatio / 2;
  const r1 = map.ratio[map.height - 1] + dRatio / 2;
  const x = (theta) => plot.x + ((theta - t0) / (t1 - t0)) * plot.w;
  const y = (ratio) => plot.y + ((r1 - ratio) / (r1 - r0)) * plot.h;
  return {
    plot,
    x,
    y,
    cellW: plot.w / map.width,
    cellH: plot.h / map.height,
    /** The cell under a CSS point, or null outside the plot. */
    cellAt(px, py) {
      if (px < plot.x || px > plot.x + plot.w || py < plot.y || py > plot.y + plot.h) return null;
      const i = Math.round((t0 + ((px - plot.x) / plot.w) * (t1 - t0) - map.thetaDeg[0]) / dTheta);
      const j = Math.round((r1 - ((py - plot.y) / plot.h) * (r1 - r0) - map.ratio[0]) / dRatio);
      return { i: Math.min(map.width - 1, Math.max(0, i)), j: Math.min(map.height - 1, Math.max(0, j)) };
    },
  };
}

function cellImage(map, colors) {
  const image = new ImageData(map.width, map.height);
  for (let j = 0; j < map.height; j += 1) {
    const row = map.height - 1 - j; // ratio grows upward
    for (let i = 0; i < map.width; i += 1) {
      const c = colors[map.cells[j * map.width + i]];
      image.data.set([c[0], c[1], c[2], 255], (row * map.width + i) * 4);
    }
  }
  const bitmap = document.createElement('canvas');
  bitmap.width = map.width;
  bitmap.height = map.height;
  bitmap.getContext('2d').putImageData(image, 0, 0);
  return bitmap;
}

function outlined(g, draw, color, width) {
  g.strokeStyle = cssVar('--panel', '#000');
  g.lineWidth = width + 3 * lineScale();
  draw();
  g.strokeStyle = color;
  g.lineWidth = width;
  draw();
}

function axes(g, L, fontPx) {
  const text = cssVar('--text', '#fff');
  g.fillStyle = text;
  g.strokeStyle = text;
  const lw = 1.5 * lineScale();
  g.lineWidth = lw;
  // The frame sits outside the plot: the first and last columns (0° and grazing) stay uncovered.
  g.strokeRect(L.plot.x - lw / 2, L.plot.y - lw / 2, L.plot.w + lw, L.plot.h + lw);
  g.textAlign = 'center';
  g.textBaseline = 'top';
  for (const t of [0, 15, 30, 45, 60, 75, 90]) {
    g.beginPath();
    g.moveTo(L.x(t), L.plot.y + L.plot.h);
    g.lineTo(L.x(t), L.plot.y + L.plot.h + fontPx * 0.35);
    g.stroke();
    g.fillText(`${t}°`, L.x(t), L.plot.y + L.plot.h + fontPx * 0.45);
  }
  g.fillText(t('mapAxisTheta'), L.plot.x + L.plot.w / 2, L.plot.y + L.plot.h + fontPx * 1.65);
  g.textAlign = 'right';
  g.textBaseline = 'middle';
  for (const r of [0.5, 1, 1.5, 2, 2.5]) {
    g.beginPath();
    g.moveTo(L.plot.x, L.y(r));
    g.lineTo(L.plot.x - fontPx * 0.35, L.y(r));
    g.stroke();
    g.fillText(fixed(r, 1), L.plot.x - fontPx * 0.45, L.y(r));
  }
  g.save();
  g.translate(fontPx * 0.9, L.plot.y + L.plot.h / 2);
  g.rotate(-Math.PI / 2);
  g.textAlign = 'center';
  g.fillText('n_i / n_t', 0, 0);
  g.restore();
}

function guides(g, L, map, fontPx) {
  const scale = lineScale();
  // Critical angle: total internal reflection to its right, on the glass side (ratio > 1). The
  // curve starts half a row above 1, where θc is already ~82°, so it never hides the matched row.
  const top = map.ratio[map.height - 1];
  const start = 1 + (top - map.ratio[0]) / (map.height - 1) / 2;
  const points = Array.from({ length: 121 }, (_, s) => start + ((top - start) * s) / 120);
  const color = cssVar('--c-exact', '#4cc9f0');
  outlined(g, () => {
    g.beginPath();
    points.forEach((r, s) => (s ? g.lineTo(L.x(criticalAngleDeg(r)), L.y(r)) : g.moveTo(L.x(criticalAngleDeg(r)), L.y(r))));
    g.stroke();
  }, color, 2.5 * scale);
  const r = 1 + (top - 1) * 0.8;
  g.font = `700 ${fontPx}px system-ui, sans-serif`;
  g.textAlign = 'left';
  g.textBaseline = 'middle';
  g.lineWidth = 4;
  g.strokeStyle = cssVar('--panel', '#000');
  g.strokeText('θc', L.x(criticalAngleDeg(r)) + fontPx * 0.5, L.y(r));
  g.fillStyle = color;
  g.fillText('θc', L.x(criticalAngleDeg(r)) + fontPx * 0.5, L.y(r));
}

function rings(g, L, map, colors) {
  let failing = 0;
  for (const c of map.cells) if (c !== FINE) failing += 1;
  if (failing === 0 || failing > RING_LIMIT) return;
  const radius = Math.max(6, 1.5 * Math.max(L.cellW, L.cellH)) * lineScale();
  for (let j = 0; j < map.height; j += 1) {
    for (let i = 0; i < map.width; i += 1) {
      const cls = map.cells[j * map.width + i];
      if (cls === FINE) continue;
      outlined(g, () => {
        g.beginPath();
        g.arc(L.x(map.thetaDeg[i]), L.y(map.ratio[j]), radius, 0, 2 * Math.PI);
        g.stroke();
      }, `rgb(${colors[cls].join(',')})`, 2 * lineScale());
    }
  }
}

/**
 * Draws map ({ cells, thetaDeg, ratio, width, height } from classify or classifyGrid) on canvas
 * at its CSS size; probe: { i, j } or null. Returns the layout (for pointer → cell).
 */
export function drawMap(canvas, map, probeCell) {
  const rect = canvas.getBoundingClientRect();
  const cssW = Math.max(50, Math.round(rect.width));
  const cssH = Math.max(50, Math.round(rect.height));
  const ratio = Math.min(2, window.devicePixelRatio || 1);
  canvas.width = Math.round(cssW * ratio);
  canvas.height = Math.round(cssH * ratio);
  const g = context2d(canvas);
  if (!g) return null;
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  const fontPx = parseFloat(getComputedStyle(canvas).fontSize) || 16;
  g.font = `${fontPx}px system-ui, sans-serif`;
  g.fillStyle = cssVar('--panel', '#161b22');
  g.fillRect(0, 0, cssW, cssH);
  const L = layout(cssW, cssH, map, fontPx);
  const colors = CLASS_COLORS.map((name) => rgb(cssVar(name)));
  g.imageSmoothingEnabled = false;
  g.drawImage(cellImage(map, colors), L.plot.x, L.plot.y, L.plot.w, L.plot.h);
  axes(g, L, fontPx);
  guides(g, L, map, fontPx);
  rings(g, L, map, colors);
  if (probeCell) {
    const size = Math.max(10, 2 * Math.max(L.cellW, L.cellH));
    outlined(g, () => g.strokeRect(L.x(map.thetaDeg[probeCell.i]) - size / 2, L.y(map.ratio[probeCell.j]) - size / 2, size, size),
      cssVar('--text', '#fff'), 2.5 * lineScale());
  }
  return L;
}
