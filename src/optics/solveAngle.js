// Angles that questions ask for and no closed form gives: where a curve of θ crosses a level, and
// where a curve peaks. Both are refined far below any question's tolerance (a grid alone would be
// off by up to half its step).
import { refinedMax } from './refinedMax.js';

/**
 * θ in degrees in [lo, hi] where f(θ) = level, by bisection; f must cross the level once there.
 * @param {(thetaDeg: number) => number} f
 * @param {number} level
 */
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
 * θ in degrees in [lo, hi] where f is largest: the best of a 0.1° grid, refined (refinedMax.js).
 * @param {(thetaDeg: number) => number} f
 */
export function angleOfMax(f, lo = 0, hi = 90) {
  const steps = Math.round((hi - lo) * 10);
  const theta = Array.from({ length: steps + 1 }, (_, i) => lo + ((hi - lo) * i) / steps);
  return refinedMax(theta, theta.map(f), f).theta;
}
