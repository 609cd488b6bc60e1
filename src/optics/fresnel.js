// Fresnel reflectance in float64: the reference every number in the lab comes from.
// Pure math, no DOM, no three.js. Its GLSL twin is shaders/fresnel.glsl (same names and branches;
// the same order of operations except where this file uses exact float64 helpers: g², which the
// GLSL factorises instead (see its cosTransmittedSq), and the conductor's 1 − c and Math.hypot).
// Conventions: θ is the angle between the normal and the incident light, cosThetaI = cos θ,
// nI is the index on the incident side and nT on the transmitted side, m = nI / nT
// (the lecture's form and GLSL refract()'s eta).
import { twoProduct, twoSum, sumPairs } from './exactArithmetic.js';
import { checkCos, checkIndex, checkExtinction, unit } from './validate.js';

/**
 * cos²θt = g² = 1 − m²(1 − cos²θi) = (1 − m²) + c², computed as (nT² − nI² + (nI·cosθi)²) / nT²:
 * the three products are formed exactly (twoProduct) and summed in double-double, so the
 * numerator is rounded once, and it is then divided by nT twice. The index part nT² − nI² is
 * exactly 0 for matched indices and good to about 2^-100 of nT² for nearly matched ones, so c² is
 * kept however small it is (the lecture's 1 + c² − m² loses it near grazing), and the numerator keeps full relative
 * precision even when it nearly cancels (just inside the critical angle).
 * Negative means total internal reflection. ci must already be checked and clamped.
 * @param {number} ci
 * @param {number} nI
 * @param {number} nT
 */
export function cosTransmittedSq(ci, nI, nT) {
  const [p, pe] = twoProduct(nI, ci); // nI·ci = p + pe exactly
  const [pp, ppe] = twoProduct(p, p);
  const numerator = sumPairs([
    twoProduct(nT, nT),
    twoProduct(-nI, nI),
    [pp, ppe + 2 * p * pe], // (p + pe)² to double-double accuracy
  ]);
  return numerator / nT / nT;
}

/**
 * Snell's law: cos θt for light going from nI into nT, or null under total internal reflection.
 * Source: Hecht, Optics (5th ed.), §4.4; g in the lecture's formula is this value.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function snellCosT(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  const g2 = cosTransmittedSq(ci, nI, nT);
  return g2 < 0 ? null : Math.sqrt(g2);
}

/**
 * Exact unpolarized dielectric reflectance, the lecture's c/g form (Cook & Torrance 1982, after
 * Sparrow & Cess): c = m cosθ, g² = cos²θt, R = ½((g−c)/(g+c))²(1 + ((c(g+c) − m²)/(c(g−c) + m²))²).
 * The lecture writes g² = 1 + c² − m²; evaluated left to right, 1 + c² rounds to 1 when c² is
 * below half an ulp of 1, so matched media near grazing get g² = 0 and R = 1 instead of 0. Here
 * g² comes from cosTransmittedSq, which never forms 1 + c²: (nI·cosθ)² = nT²c² is added to the
 * index part nT² − nI², which is tiny and accurate for nearly matched indices, so c² is not lost
 * and that failure is gone. Matched indices return 0 before g² is needed.
 * g² ≤ 0 is total internal reflection: R = 1.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelExact(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  if (nI === nT) return 0; // no interface: nothing reflects, at grazing too
  const g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0) return 1;
  const g = Math.sqrt(g2);
  const c = (nI * ci) / nT;
  const a = (g - c) / (g + c);
  // The lecture's (c(g+c) − m²)/(c(g−c) + m²) with c² − m² = −m²sin²θi substituted: no difference
  // of two large, nearly equal terms (c² and m² near the critical angle, g² and 1 for small m).
  const m = nI / nT;
  const ms2 = m * m * ((1 - ci) * (1 + ci));
  const cg = c * g;
  const b = (cg - ms2) / (cg + ms2);
  return unit(0.5 * a * a * (1 + b * b));
}

/**
 * s- and p-polarized power reflectances (Fresnel equations; Hecht, Optics §4.6.2):
 * rs = (nI cosθi − nT cosθt)/(nI cosθi + nT cosθt), rp = (nT cosθi − nI cosθt)/(nT cosθi + nI cosθt).
 * Their mean is fresnelExact. Total internal reflection: both 1.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelPolarized(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  if (nI === nT) return { s: 0, p: 0 };
  const g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0) return { s: 1, p: 1 };
  const ct = Math.sqrt(g2);
  const rs = (nI * ci - nT * ct) / (nI * ci + nT * ct);
  const rp = (nT * ci - nI * ct) / (nT * ci + nI * ct);
  return { s: unit(rs * rs), p: unit(rp * rp) };
}

/**
 * Power transmittances per polarization, T = (nT cosθt)/(nI cosθi)·|t|², written without the
 * division by cosθi so grazing incidence gives 0 rather than 0/0 (Hecht, Optics §4.6.3).
 * Rs + Ts = 1 and Rp + Tp = 1; `unpolarized` is their mean.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelTransmittance(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  if (nI === nT) return { s: 1, p: 1, unpolarized: 1 };
  const g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0) return { s: 0, p: 0, unpolarized: 0 };
  const ct = Math.sqrt(g2);
  const num = 4 * nI * ci * nT * ct;
  const ds = nI * ci + nT * ct;
  const dp = nT * ci + nI * ct;
  const s = unit(num / (ds * ds));
  const p = unit(num / (dp * dp));
  return { s, p, unpolarized: 0.5 * (s + p) };
}

/**
 * R0 = R(0°) = ((nT − nI)/(nT + nI))², the same for both directions (lecture, R(0°) derivation).
 * @param {number} nI
 * @param {number} nT
 */
export function normalIncidence(nI, nT) {
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  const r = (nT - nI) / (nT + nI);
  return r * r;
}

/**
 * Schlick's polynomial on a given cosine; (1 − c)^5 by multiplications, as GLSL does it.
 * @param {number} c
 * @param {number} r0
 */
function schlickOn(c, r0) {
  const x = 1 - c;
  const x2 = x * x;
  return unit(r0 + (1 - r0) * (x2 * x2 * x));
}

/**
 * Schlick's approximation as on the slide: R0 + (1 − R0)(1 − cosθi)^5
 * (Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", CGF 13(3), 1994).
 * It has no total internal reflection: from glass to air it is wrong by up to 0.96.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelSchlick(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  return schlickOn(ci, normalIncidence(nI, nT));
}

/**
 * Schlick on the larger angle: cos θt when nI > nT, and 1 past the critical angle
 * (R(θi, inside) = R(θt, outside); Shirley, "Bug in my Schlick code", 2016; Cycles
 * generalized_schlick_fresnel). The same as fresnelSchlick when nI ≤ nT.
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelSchlickTIR(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  const r0 = normalIncidence(nI, nT);
  if (nI <= nT) return schlickOn(ci, r0);
  const g2 = cosTransmittedSq(ci, nI, nT);
  return g2 <= 0 ? 1 : schlickOn(Math.sqrt(g2), r0);
}

/**
 * The spherical-Gaussian Schlick form three.js uses in F_Schlick (bsdfs.glsl.js):
 * R0 + (1 − R0)·2^((−5.55473c − 6.98316)c) (Karis, "Real Shading in Unreal Engine 4", 2013).
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function fresnelSchlickExp2(cosThetaI, nI, nT) {
  const c = checkCos(cosThetaI);
  const r0 = normalIncidence(nI, nT);
  return unit(r0 + (1 - r0) * Math.pow(2, (-5.55473 * c - 6.98316) * c));
}

/**
 * Critical angle asin(nT/nI) in radians when nI > nT; null when there is none.
 * @param {number} nI
 * @param {number} nT
 */
export function criticalAngle(nI, nT) {
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  return nI > nT ? Math.asin(nT / nI) : null;
}

/**
 * Brewster angle atan(nT/nI) in radians, where Rp = 0 (Hecht, Optics §8.6.1).
 * @param {number} nI
 * @param {number} nT
 */
export function brewsterAngle(nI, nT) {
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  return Math.atan2(nT, nI);
}

/**
 * Conductor reflectance per polarization, from air (index 1) into n + ik.
 * Real-arithmetic form (Lagarde, "Memo on Fresnel equations", 2013; pbrt-v3 FrConductor), with
 * a² + b² = |η² − sin²θ| and ab = nk, and each of a², b² taken from whichever formula does not
 * cancel. Rs = ((a − c)² + b²)/((a + c)² + b²), Rp = Rs((ac − s²)² + (bc)²)/((ac + s²)² + (bc)²).
 * @param {number} cosThetaI
 * @param {number} n
 * @param {number} k
 */
export function fresnelConductorPolarized(cosThetaI, n, k) {
  const c = checkCos(cosThetaI);
  checkIndex(n, 'n');
  checkExtinction(k, 'k');
  const [s2hi, s2lo] = twoSum(1, -c); // 1 − c exactly when c ≥ 0.5
  const sin2 = (s2hi + s2lo) * (1 + c);
  const t0 = n * n - k * k - sin2;
  const nk = n * k;
  const S = Math.hypot(t0, 2 * nk);
  let a2;
  let b2;
  if (t0 >= 0) {
    a2 = 0.5 * (S + t0);
    b2 = a2 > 0 ? (nk * nk) / a2 : 0;
  } else {
    b2 = 0.5 * (S - t0);
    a2 = (nk * nk) / b2;
  }
  const a = Math.sqrt(a2);
  const b = Math.sqrt(b2);
  const dm = a - c;
  const dp = a + c;
  const rs = (dm * dm + b2) / (dp * dp + b2);
  if (!(rs > 0)) return { s: 0, p: 0 }; // n = 1, k = 0 at normal incidence: no interface
  const um = a * c - sin2;
  const up = a * c + sin2;
  const bc = b * c;
  const rp = rs * ((um * um + bc * bc) / (up * up + bc * bc));
  return { s: unit(rs), p: unit(Number.isFinite(rp) ? rp : rs) };
}

/**
 * Exact unpolarized reflectance from air into a conductor with complex index n + ik.
 * @param {number} cosThetaI
 * @param {number} n
 * @param {number} k
 */
export function fresnelConductor(cosThetaI, n, k) {
  const { s, p } = fresnelConductorPolarized(cosThetaI, n, k);
  return unit(0.5 * (s + p));
}

/**
 * Conductor R0 = ((n − 1)² + k²)/((n + 1)² + k²).
 * @param {number} n
 * @param {number} k
 */
export function conductorNormalIncidence(n, k) {
  checkIndex(n, 'n');
  checkExtinction(k, 'k');
  return ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k);
}
