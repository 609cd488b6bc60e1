// The speed/accuracy scatter's marks: the budget as a dashed line, the Pareto front as a staircase
// (right, then down) with its key above the plot, and each method's point with its spread bar:
// filled within the budget, hollow over it (colour is not the only cue), ringed if recommended.

/**
 * Draws the marks and returns the points drawn with their canvas positions, for the labels.
 * @param {CanvasRenderingContext2D} g
 * @returns {{ p: any, px: number, py: number }[]}
 */
export function drawPoints(g, frame, colors) {
  const { box, s, font, X, Y, pointY, data } = frame;
  const { points } = data;
  g.strokeStyle = colors.budget;
  g.lineWidth = 3 * s;
  g.setLineDash([10 * s, 6 * s]);
  g.beginPath();
  g.moveTo(box.left, Y(data.budget.codes));
  g.lineTo(box.right, Y(data.budget.codes));
  g.stroke();
  g.setLineDash([]);

  const front = data.front.map((i) => points[i]);
  if (front.length) {
    g.strokeStyle = colors.front;
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
    g.fillStyle = colors.front;
    g.fillRect(box.left, frame.keyY - 1.5 * s, 28 * s, 3 * s);
    g.fillText(data.words.front, box.left + 36 * s, frame.keyY);
  }

  const drawn = points.filter((p) => Number.isFinite(p.x)).map((p) => ({ p, px: X(p.x), py: pointY(p) }));
  for (const { p, px, py } of drawn) {
    const color = p.passes ? colors.pass : colors.fail;
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
      g.fillStyle = color;
      g.fill();
    } else {
      g.strokeStyle = color;
      g.lineWidth = 3 * s;
      g.stroke();
    }
    if (p.recommended) {
      g.strokeStyle = colors.budget;
      g.lineWidth = 3 * s;
      g.beginPath();
      g.arc(px, py, 13 * s, 0, 2 * Math.PI);
      g.stroke();
    }
  }
  return drawn;
}
