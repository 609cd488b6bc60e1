// Angles that questions ask for and no closed form gives: where a curve of θ crosses a level, and
// where a curve peaks. Both start from a grid and refine, so the answer is good to far below any
// question's tolerance (the grid alone would be off by up to half its step).

/** θ in degrees in [lo, hi] where f(θ) = level, by bisection; f must cross the level once there. */
export function angleWhere(f, level, lo = 0, hi = 90) {
  let a = lo;
  let b = hi;
  const below = f(a) < level;
  if ((f(b) < level) === below) throw new RangeError(`f does not cross ${level} between ${lo}° and ${hi}°`);
  for (let i = 0; i < 80 && b - a > 1e-12; i += 1) {
    const m = (a + b) / 2;
    if ((f(m) < level) === below) a = m;
    else b = m;
  }
  return (a + b) / 2;
}

/**
 * θ in degrees in [lo, hi] where f is largest: the best of a 0.1° grid, then a golden-section
 * search in the two grid steps around it (f is taken to be unimodal there).
 */
export function angleOfMax(f, lo = 0, hi = 90) {
  const steps = Math.round((hi - lo) * 10);
  let best = lo;
  for (let i = 0; i <= steps; i += 1) {
    const t = lo + ((hi - lo) * i) / steps;
    if (f(t) > f(best)) best = t;
  }
  const step = (hi - lo) / steps;
  let a = Math.max(lo, best - step);
  let b = Math.min(hi, best + step);
  const r = (Math.sqrt(5) - 1) / 2;
  let c = b - r * (b - a);
  let d = a + r * (b - a);
  for (let i = 0; i < 100 && b - a > 1e-10; i += 1) {
    if (f(c) > f(d)) b = d;
    else a = c;
    c = b - r * (b - a);
    d = a + r * (b - a);
  }
  return (a + b) / 2;
}
