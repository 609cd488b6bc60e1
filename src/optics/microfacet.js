// GGX (Trowbridge–Reitz) microfacet specular in float64: the normal distribution D, Smith's
// height-correlated masking-shadowing G2 and the Cook–Torrance BRDF D·G·F / (4 cosθl cosθv).
// Pure math, no DOM. Its GLSL twin is shaders/microfacet.glsl (same names, same order).
// alpha is the GGX width; the common artist mapping is alpha = roughness² (Burley, "Physically
// Based Shading at Disney", SIGGRAPH 2012 course notes, §5.4).
import { checkCos, unit } from './validate.js';

/**
 * @param {number} alpha
 */
function checkAlpha(alpha) {
  if (typeof alpha !== 'number' || !Number.isFinite(alpha) || alpha <= 0) {
    throw new RangeError(`alpha must be a finite number > 0, got ${String(alpha)}`);
  }
  return alpha;
}

/**
 * GGX normal distribution D(h) = α² / (π ((n·h)²(α² − 1) + 1)²), normalized so that
 * ∫ D(h) (n·h) dω = 1 (Walter et al., "Microfacet Models for Refraction through Rough Surfaces",
 * EGSR 2007, eq. 33). The denominator's base is written (1 − c)(1 + c) + c²α²: the same value,
 * but at the peak (c → 1) the textbook c²(α² − 1) + 1 subtracts nearly equal terms and loses α²
 * in float32 (a few % at α = 1e-3, and +Infinity below α ≈ 1.7e-4).
 * @param {number} cosThetaH
 * @param {number} alpha
 */
export function ggxDistribution(cosThetaH, alpha) {
  const c = checkCos(cosThetaH, 'cosThetaH');
  const a2 = checkAlpha(alpha) ** 2;
  const d = (1 - c) * (1 + c) + c * c * a2;
  return a2 / (Math.PI * d * d);
}

/**
 * Smith's Λ for GGX, Λ(θ) = (−1 + √(1 + α² tan²θ)) / 2, written with tan²θ = (1 − c²)/c² as
 * (√(c² + α²(1 − c²)) / c − 1) / 2 so it has no tan (Heitz, "Understanding the Masking-Shadowing
 * Function in Microfacet-Based BRDFs", JCGT 3(2), 2014, eq. 72). Infinite at grazing (c = 0).
 * @param {number} cosTheta
 * @param {number} alpha
 */
export function smithLambda(cosTheta, alpha) {
  const c = checkCos(cosTheta, 'cosTheta');
  const a2 = checkAlpha(alpha) ** 2;
  if (c === 0) return Infinity;
  return 0.5 * (Math.sqrt(c * c + a2 * ((1 - c) * (1 + c))) / c - 1);
}

/**
 * Height-correlated masking-shadowing G2 = 1 / (1 + Λ(l) + Λ(v)) (Heitz 2014, eq. 99); 0 when
 * either direction is at or below the surface (Λ = ∞ there), said outright so the float32 twin
 * needs no infinity.
 * @param {number} cosL
 * @param {number} cosV
 * @param {number} alpha
 */
export function smithG2(cosL, cosV, alpha) {
  if (!(cosL > 0) || !(cosV > 0)) return 0;
  return 1 / (1 + smithLambda(cosL, alpha) + smithLambda(cosV, alpha));
}

/**
 * Cook–Torrance specular BRDF f = D·G2·F / (4 cosθl cosθv) (Cook & Torrance, "A Reflectance Model
 * for Computer Graphics", ACM TOG 1(1), 1982; with Walter et al.'s D and Heitz's G2). F is the
 * Fresnel reflectance at the half-vector angle, supplied by the caller (src/optics/fresnel.js).
 * 0 when either direction is at or below the surface.
 * @param {{ cosL: number, cosV: number, cosH: number, alpha: number, F: number }} terms
 */
export function microfacetSpecular({ cosL, cosV, cosH, alpha, F }) {
  if (!(cosL > 0) || !(cosV > 0)) return 0;
  const D = ggxDistribution(cosH, alpha);
  const G = smithG2(cosL, cosV, alpha);
  return (D * G * unit(F)) / (4 * checkCos(cosL, 'cosL') * checkCos(cosV, 'cosV'));
}
