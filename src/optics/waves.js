// Plane waves at a flat interface between two media: wavelength and phase speed in each medium,
// the direction bent by Snell's law, total internal reflection, and the s-polarized field
// amplitudes that the refraction-waves panel draws. Pure math, no DOM.
// Power fractions come from fresnel.js; this file adds only what fresnel.js has no use for:
// the signs and phases of the field amplitudes, and the wave vectors.
// Convention: field = Re{A·exp(i(k·r − ωt))}; the interface is y = 0, medium 1 (n1) above it,
// the incident wave travels downward at θ1 from the normal.
import { fresnelPolarized, snellCosT } from './fresnel.js';
import { checkIndex } from './validate.js';

/** c in km/s, exact by the SI definition of the metre (17th CGPM, 1983). */
export const SPEED_OF_LIGHT_KM_S = 299_792.458;

/**
 * @param {number} theta
 */
function checkAngle(theta) {
  if (typeof theta !== 'number' || !Number.isFinite(theta) || theta < 0 || theta > Math.PI / 2) {
    throw new RangeError(`theta1 must be an angle in [0, π/2] radians, got ${String(theta)}`);
  }
  return theta;
}

/**
 * In a medium of index n the frequency stays that of the source while the phase speed drops
 * to c/n, so the wavelength shrinks to λ0/n (Hecht, Optics 5th ed., §3.5.1 and §4.2).
 * speed is a fraction of c; wavelength is in the units of lambda0.
 * @param {number} n
 */
export function mediumWave(n, lambda0 = 1) {
  checkIndex(n, 'n');
  return { wavelength: lambda0 / n, speed: 1 / n, speedKmS: SPEED_OF_LIGHT_KM_S / n };
}

/**
 * True when no propagating transmitted wave exists (only an evanescent one): n1 sin θ1 > n2 (Snell gives sin θ2 > 1).
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function isTotalInternalReflection(theta1, n1, n2) {
  return snellCosT(Math.cos(checkAngle(theta1)), n1, n2) === null;
}

/**
 * Snell's law n1 sin θ1 = n2 sin θ2 (Hecht §4.4): θ2 in radians, or null under total internal
 * reflection. atan2 of sine and cosine keeps full precision near 0° and near 90°.
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function transmittedAngle(theta1, n1, n2) {
  const cosT = snellCosT(Math.cos(checkAngle(theta1)), n1, n2);
  if (cosT === null) return null;
  return Math.atan2((n1 / n2) * Math.sin(theta1), cosT);
}

/**
 * Complex amplitude r_s of the reflected s-polarized field for a unit incident field.
 * Its magnitude is √Rs from fresnelPolarized. Outside total internal reflection r_s is real:
 * (n1 cosθ1 − n2 cosθ2)/(n1 cosθ1 + n2 cosθ2) is negative into a denser medium (a half-wave
 * flip) and positive into a less dense one (Hecht §4.6.2). Under total internal reflection
 * r_s = (a − ib)/(a + ib) with a = n1 cosθ1, b = √(n1² sin²θ1 − n2²): |r_s| = 1 with phase
 * −2 atan(b/a) (Hecht §4.7; Born & Wolf, Principles of Optics, §1.5.4).
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function reflectionAmplitudeS(theta1, n1, n2) {
  const cosI = Math.cos(checkAngle(theta1));
  if (snellCosT(cosI, n1, n2) !== null) {
    const magnitude = Math.sqrt(fresnelPolarized(cosI, n1, n2).s);
    return { re: n1 < n2 ? -magnitude : magnitude, im: 0 };
  }
  const sinI = Math.sin(theta1);
  const b = Math.sqrt((n1 * sinI - n2) * (n1 * sinI + n2));
  const phase = -2 * Math.atan2(b, n1 * cosI);
  return { re: Math.cos(phase), im: Math.sin(phase) };
}

/**
 * Complex amplitude t_s of the transmitted (or evanescent) s-polarized field: the tangential
 * field is continuous across the interface, so t_s = 1 + r_s (Hecht §4.6.2).
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function transmissionAmplitudeS(theta1, n1, n2) {
  const r = reflectionAmplitudeS(theta1, n1, n2);
  return { re: 1 + r.re, im: r.im };
}

/**
 * 1/e decay depth of the evanescent field below the interface under total internal reflection,
 * 1/κ with κ = (2π/λ0)·√(n1² sin²θ1 − n2²) (Hecht §4.7); null when a wave is transmitted.
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function evanescentDepth(theta1, n1, n2, lambda0 = 1) {
  if (!isTotalInternalReflection(theta1, n1, n2)) return null;
  const sinI = Math.sin(theta1);
  return lambda0 / (2 * Math.PI * Math.sqrt((n1 * sinI - n2) * (n1 * sinI + n2)));
}

/**
 * Everything a wave picture needs, in units of the vacuum wavelength lambda0 (angular wave
 * numbers, radians per unit length). kx, the component along the interface, is the same in both
 * media (that is Snell's law, and why the wavefronts meet at the boundary); k1y and k2y are the
 * components along the downward normal; kappa is the evanescent decay rate (0 unless TIR).
 * @param {number} theta1
 * @param {number} n1
 * @param {number} n2
 */
export function waveField(theta1, n1, n2, lambda0 = 1) {
  checkIndex(n1, 'n1');
  checkIndex(n2, 'n2');
  const k0 = (2 * Math.PI) / lambda0;
  const theta2 = transmittedAngle(theta1, n1, n2);
  const tir = theta2 === null;
  const sinI = Math.sin(theta1);
  return {
    tir,
    theta2,
    kx: k0 * n1 * sinI,
    k1y: k0 * n1 * Math.cos(theta1),
    k2y: tir ? 0 : k0 * n2 * Math.cos(theta2),
    kappa: tir ? k0 * Math.sqrt((n1 * sinI - n2) * (n1 * sinI + n2)) : 0,
    r: reflectionAmplitudeS(theta1, n1, n2),
    t: transmissionAmplitudeS(theta1, n1, n2),
  };
}

/**
 * The field the panel draws at (x, y) (in λ0) and phase ωt, from a waveField() result: above the
 * interface the incident wave (plus the reflected one when asked), below it the transmitted or
 * evanescent wave. The JS twin of src/panels/refraction-waves/refraction-waves.frag.glsl, for tests and probes.
 * @param {ReturnType<typeof waveField>} w
 * @param {number} x
 * @param {number} y
 * @param {number} phase
 */
export function fieldAt(w, x, y, phase, withReflected = false) {
  const along = w.kx * x - phase;
  const re = (/** @type {{ re: number, im: number }} */ z, /** @type {number} */ phi) => z.re * Math.cos(phi) - z.im * Math.sin(phi);
  if (y >= 0) return Math.cos(along - w.k1y * y) + (withReflected ? re(w.r, along + w.k1y * y) : 0);
  if (w.tir) return Math.exp(w.kappa * y) * re(w.t, along);
  return re(w.t, along - w.k2y * y);
}
