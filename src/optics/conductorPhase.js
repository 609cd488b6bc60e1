// The phase a conductor adds between p- and s-polarized reflection, and the two angles that stand in
// for Brewster's on a metal: the pseudo-Brewster angle, where Rp is least (the metals panel's physics.js finds it),
// and the principal angle, where the p–s phase difference is 90° (Born & Wolf, Principles of
// Optics, 7th ed., §14.2; the two differ by a few degrees: Azzam, JOSA A 25, 2858, 2008).
// Pure float64 math, from air (index 1) into n + ik.
import { checkCos, checkExtinction, checkIndex } from './validate.js';
import { DEG, toDegrees } from './angles.js';

/**
 * The complex amplitude coefficients rs and rp as [re, im] pairs, in the convention where rp = −rs
 * head-on (Born & Wolf §1.5.2): with w = √(η² − sin²θ) (η = n + ik, the root with Re w ≥ 0),
 * rs = (cos θ − w)/(cos θ + w) and rp = (η² cos θ − w)/(η² cos θ + w).
 */
export function conductorAmplitudes(cosThetaI, n, k) {
  const c = checkCos(cosThetaI);
  checkIndex(n, 'n');
  checkExtinction(k, 'k');
  const sin2 = (1 - c) * (1 + c);
  const eta2 = [n * n - k * k, 2 * n * k];
  const w = complexSqrt([eta2[0] - sin2, eta2[1]]);
  const rs = divide([c - w[0], -w[1]], [c + w[0], w[1]]);
  const e = [eta2[0] * c, eta2[1] * c];
  const rp = divide([e[0] - w[0], e[1] - w[1]], [e[0] + w[0], e[1] + w[1]]);
  return { rs, rp };
}

/**
 * Δ = arg(rp/rs) in degrees, the p–s phase difference on reflection: 180° head-on (rp = −rs),
 * falling to 0° at grazing for an absorbing metal (k > 0).
 */
export function conductorPhaseDifference(cosThetaI, n, k) {
  const { rs, rp } = conductorAmplitudes(cosThetaI, n, k);
  const ratio = divide(rp, rs);
  return Math.abs(toDegrees(Math.atan2(ratio[1], ratio[0])));
}

/**
 * The principal angle of incidence in degrees, where Δ = 90° (Born & Wolf §14.2), found by
 * bisection between Δ = 180° head-on and Δ = 0° at grazing. For the lab's metals Δ falls
 * monotonically, so there is one (a unit test checks it); a weakly absorbing medium with n < 1 can
 * have three (Azzam 2008), of which bisection finds one. Null for k = 0, where Δ jumps from 180°
 * to 0° at Brewster's angle instead.
 */
export function principalAngle(n, k) {
  if (!(k > 0)) return null;
  const delta = (t) => conductorPhaseDifference(Math.cos(t * DEG), n, k);
  let lo = 0;
  let hi = 90;
  for (let i = 0; i < 60; i += 1) {
    const mid = (lo + hi) / 2;
    if (delta(mid) > 90) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

function divide([a, b], [c, d]) {
  const q = c * c + d * d;
  return [(a * c + b * d) / q, (b * c - a * d) / q];
}

/** The principal square root of x + iy (Re ≥ 0), without cancellation on either side of the axis. */
function complexSqrt([x, y]) {
  const r = Math.hypot(x, y);
  if (r === 0) return [0, 0];
  if (x >= 0) {
    const re = Math.sqrt((r + x) / 2);
    return [re, y / (2 * re)];
  }
  const im = Math.sqrt((r - x) / 2) * (y < 0 ? -1 : 1);
  return [y / (2 * im), im];
}
