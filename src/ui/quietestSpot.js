// Where a plot's marker label goes: of the boxes it may take, the one that covers the fewest curve
// samples and no label already placed; ties go to the earlier (preferred) box. A label left at
// the top by habit hides what it names whenever a curve runs along the top: a metal's exact curve
// dipping just below F0 near R = 1, or the R = 1 line of total internal reflection.

const overlaps = (a, b) => a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;

/**
 * spots: candidate boxes { x0, x1, y0, y1 } in order of preference. points: [x, y] pixel positions
 * of the curves' samples. taken: boxes already placed. Returns the chosen spot.
 */
export function quietestSpot(spots, points, taken) {
  const within = new Map(); // the samples under each column of spots, found once per column
  let best = spots[0];
  let bestCost = Infinity;
  for (const spot of spots) {
    const key = `${spot.x0} ${spot.x1}`;
    if (!within.has(key)) within.set(key, points.filter(([x]) => x >= spot.x0 && x <= spot.x1).map(([, y]) => y));
    const blocked = taken.some((t) => overlaps(spot, t));
    let cost = blocked ? points.length + 1 : 0;
    for (const y of within.get(key)) if (y >= spot.y0 && y <= spot.y1) cost += 1;
    if (cost < bestCost) {
      best = spot;
      bestCost = cost;
    }
  }
  return best;
}
