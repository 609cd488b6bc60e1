// Sampled R(θ) curves for plots and CSV export, all from the float64 reference functions.
import {
  brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized, fresnelSchlick,
} from './fresnel.js';
import { cosDeg, DEG } from './angles.js';
import { refinedMax } from './refinedMax.js';


/** θ in degrees from 0 to 90 in `count` steps, with the critical and Brewster angles inserted
 *  so the curves' corner and dip are drawn exactly where they are.
 * @param {number} nI
 * @param {number} nT
 */
export function sampleAngles(nI, nT, count = 361) {
  const angles = Array.from({ length: count }, (_, i) => (90 * i) / (count - 1));
  const critical = criticalAngle(nI, nT);
  const extra = [brewsterAngle(nI, nT) / DEG];
  if (critical !== null) extra.push(critical / DEG);
  return [...new Set([...angles, ...extra])].sort((a, b) => a - b);
}

/**
 * Exact, Schlick, Rs, Rp and |exact − Schlick| at each angle (degrees).
 * @param {number} nI
 * @param {number} nT
 */
export function reflectanceCurves(nI, nT, count = 361) {
  const theta = sampleAngles(nI, nT, count);
  const exact = [];
  const schlick = [];
  const s = [];
  const p = [];
  const error = [];
  for (const t of theta) {
    const c = cosDeg(t);
    const e = fresnelExact(c, nI, nT);
    const sc = fresnelSchlick(c, nI, nT);
    const sp = fresnelPolarized(c, nI, nT);
    exact.push(e);
    schlick.push(sc);
    s.push(sp.s);
    p.push(sp.p);
    error.push(Math.abs(e - sc));
  }
  return { theta, exact, schlick, s, p, error };
}

/**
 * |exact − Schlick (on cos θi)| at θ in degrees, for nI → nT.
 * @param {number} thetaDeg
 * @param {number} nI
 * @param {number} nT
 */
export function schlickErrorAt(thetaDeg, nI, nT) {
  const c = cosDeg(thetaDeg);
  return Math.abs(fresnelExact(c, nI, nT) - fresnelSchlick(c, nI, nT));
}

/**
 * Largest |exact − Schlick| for nI → nT and the angle (degrees) where it occurs: the sampled
 * curve's largest, refined between its neighbours (refinedMax.js).
 * @param {{ theta: readonly number[], error: readonly number[] }} curves
 * @param {number} nI
 * @param {number} nT
 */
export function maxError({ theta, error }, nI, nT) {
  return refinedMax(theta, error, (t) => schlickErrorAt(t, nI, nT));
}

/**
 * A round number at or above x on the 1-2-5 ladder, for a legend's top value.
 * @param {number} x
 */
export function niceCeil(x) {
  if (!(x > 0)) return 0.01;
  const exponent = Math.floor(Math.log10(x));
  const base = 10 ** exponent;
  const step = [1, 2, 5, 10].find((k) => k * base >= x * (1 - 1e-12)) ?? 10; // 10 always holds: x < 10·base
  return step * base;
}
