// The numbers of the reflect-refract panel, pure (no DOM) so Node tests can pin them: the split
// of light between the reflected sky and the refracted floor for the ray through the centre of
// the view, and which of the lecture's three captions it falls in (their words are words.js's).
// Light comes from air (n_i = 1) onto water or glass (n_t = n).
import { fresnelExact, snellCosT } from '../../optics/fresnel.js';
import { DEG } from '../../optics/angles.js';

/** A caption's band: its id and its upper bound of R. */
const band = (id, below) => Object.freeze({ id, below });

/**
 * The lecture's captions ("Reflection vs. Refraction" slide), assigned by the reflected fraction R
 * of the ray through the centre. The thresholds are this panel's reading of the photographs:
 * under 10% the floor dominates the picture, from 40% the sky does. The slide's lowest caption is
 * "No reflection"; no view reflects nothing (water head-on reflects 0.02), so it reads "little".
 */
export const REFLECTION_BANDS = Object.freeze([band('none', 0.1), band('some', 0.4), band('lots', Infinity)]);

/** Where nothing is reflected at all (n_t = 1: no interface), the caption says so. */
export const NO_REFLECTION = band('nothing', 0);

export function reflectionBand(R) {
  if (R === 0) return NO_REFLECTION;
  return REFLECTION_BANDS.find((band) => R < band.below);
}

/**
 * The centre ray of a camera looking down at `elevationDeg` above a flat surface: its angle from
 * the normal is 90° − elevation, so cos θ = sin(elevation). R from the exact Fresnel formula,
 * T = 1 − R (no absorption), θt from Snell's law (always exists: air into a denser medium).
 * floorWeight = T/n² weighs the floor's radiance as seen from the air: light leaving the water
 * spreads into a wider cone, so its radiance falls by (n_i/n_t)² (radiance over n² is what a
 * refraction keeps; Pharr, Jakob & Humphreys, Physically Based Rendering, 3rd ed., §16.1.3).
 */
export function centreRay(elevationDeg, n) {
  const cosI = Math.sin(elevationDeg * DEG);
  const R = fresnelExact(cosI, 1, n);
  const cosT = snellCosT(cosI, 1, n);
  const sinT = Math.sqrt((1 - cosI) * (1 + cosI)) / n;
  return {
    thetaDeg: 90 - elevationDeg,
    R,
    T: 1 - R,
    floorWeight: (1 - R) / (n * n),
    thetaTDeg: Math.atan2(sinT, cosT) / DEG,
    band: reflectionBand(R),
  };
}

/** R and T of the centre ray against the view elevation, for the CSV export. */
export function splitByElevation(n, from = 1, to = 90, step = 0.5) {
  const elevation = [];
  const R = [];
  const T = [];
  for (let i = 0; from + i * step <= to + 1e-9; i += 1) {
    const e = from + i * step;
    const ray = centreRay(e, n);
    elevation.push(e);
    R.push(ray.R);
    T.push(ray.T);
  }
  return { elevation, R, T };
}
