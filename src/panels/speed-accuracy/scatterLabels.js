// The speed/accuracy scatter's words over its marks: each method's name beside its point, nudged
// up or down where names crowd (with a leader line back to the point), and the budget's label.
// Labels are placed first, then leaders drawn, then every label on its background over them, so
// no line runs through a name.

/**
 * Spots for labels of widths `widths[i]` beside points `drawn[i]` (in order of x): the first spot
 * inside the box that covers nothing already taken, failing that (a crowded narrow chart) the spot
 * inside that covers the least; a point hidden costs far more than a label overlapped (weight).
 * @param {{ px: number, py: number }[]} drawn
 * @param {number[]} widths
 * @param {{ x0: number, x1: number, y0: number, y1: number, weight?: number }[]} taken kept clear, grown by each label placed
 */
export function placeLabels(drawn, widths, { box, s, lineH }, taken) {
  const rectAt = (c, w) => ({ x0: c.x - 3, x1: c.x + w + 3, y0: c.y - lineH / 2, y1: c.y + lineH / 2 });
  const inside = (r) => r.x0 >= box.left && r.x1 <= box.right && r.y0 >= box.top && r.y1 <= box.bottom;
  const covered = (r) => taken.reduce((sum, t) => sum + (t.weight ?? 1)
    * Math.max(0, Math.min(r.x1, t.x1) - Math.max(r.x0, t.x0)) * Math.max(0, Math.min(r.y1, t.y1) - Math.max(r.y0, t.y0)), 0);
  return drawn.map(({ px, py }, i) => {
    const w = widths[i];
    const candidates = [];
    for (const k of [0, -1, 1, -2, 2, -3, 3, -4, 4, -5, 5, -6, 6, -7, 7, -8, 8]) {
      candidates.push({ x: px + 16 * s, y: py + k * lineH }, { x: px - 16 * s - w, y: py + k * lineH });
    }
    const inBox = candidates.filter((c) => inside(rectAt(c, w)));
    const spot = inBox.find((c) => covered(rectAt(c, w)) === 0)
      ?? inBox.reduce((best, c) => (best && covered(rectAt(best, w)) <= covered(rectAt(c, w)) ? best : c), null)
      ?? candidates[0];
    const rect = rectAt(spot, w);
    taken.push(rect);
    return { spot, rect };
  });
}

/**
 * @param {CanvasRenderingContext2D} g
 * @param {{ p: any, px: number, py: number }[]} drawn the points as drawPoints placed them
 */
export function drawLabels(g, frame, colors, drawn) {
  const { box, s, font, Y, data } = frame;
  const lineH = 22 * s;
  g.font = font(15, true);
  g.textBaseline = 'middle';
  g.textAlign = 'left';
  const budgetText = data.budget.label;
  const budgetY = Y(data.budget.codes);
  const budgetRect = {
    x0: box.left + 4, x1: box.left + 12 + g.measureText(budgetText).width, y0: budgetY - 4 - 18 * s, y1: budgetY + 2 * s,
  };
  const pointRects = drawn.map(({ px, py }) => ({ x0: px - 9 * s, x1: px + 9 * s, y0: py - 9 * s, y1: py + 9 * s, weight: 50 }));
  const taken = [budgetRect, ...pointRects];
  const byX = [...drawn].sort((a, b) => a.px - b.px);
  const labels = byX.map(({ p }) => (p.recommended ? `${p.name} ★` : p.name));
  const spots = placeLabels(byX, labels.map((label) => g.measureText(label).width), { box, s, lineH }, taken);
  const placed = byX.map(({ px, py }, i) => ({ label: labels[i], px, py, ...spots[i] }));

  g.strokeStyle = colors.text;
  g.lineWidth = 1.5 * s;
  for (const { px, py, spot, rect } of placed) {
    if (Math.abs(spot.y - py) <= 1) continue;
    g.beginPath();
    g.moveTo(px, py);
    g.lineTo(spot.x > px ? rect.x0 : rect.x1, spot.y);
    g.stroke();
  }
  g.fillStyle = colors.labelBg;
  g.fillRect(budgetRect.x0, budgetRect.y0, budgetRect.x1 - budgetRect.x0, budgetRect.y1 - budgetRect.y0 - 4 * s);
  g.fillStyle = colors.budget;
  g.textBaseline = 'bottom';
  g.fillText(budgetText, box.left + 8, budgetY - 4);
  g.textBaseline = 'middle';
  for (const { label, spot, rect } of placed) {
    g.fillStyle = colors.labelBg;
    g.fillRect(rect.x0, rect.y0 + 1, rect.x1 - rect.x0, lineH - 2);
    g.fillStyle = colors.text;
    g.fillText(label, spot.x, spot.y);
  }
}
