// The Pareto front of a cost/error scatter: the methods that no other method beats on both
// axes at once (cheaper and at least as accurate, or as cheap and more accurate). Everything
// off the front is a method one should never pick, whatever the budget.

/**
 * Indices of the non-dominated points of [{ x: cost, y: error }] (lower is better on both), in
 * order of increasing cost. A point with a non-finite cost or error (NaN output) is never on the
 * front; of points equal on both axes only the first is kept.
 */
export function paretoFront(points) {
  const order = points
    .map((p, i) => i)
    .filter((i) => Number.isFinite(points[i].x) && Number.isFinite(points[i].y))
    .sort((a, b) => points[a].x - points[b].x || points[a].y - points[b].y || a - b);
  const front = [];
  let best = Infinity;
  for (const i of order) {
    if (points[i].y < best) {
      front.push(i);
      best = points[i].y;
    }
  }
  return front;
}
