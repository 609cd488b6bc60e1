// The exact Fresnel formula term by term, for a panel that shows every intermediate value.
// Pure float64 math, no DOM. fresnelTerms follows src/optics/fresnel.js step for step (same g²,
// same rewritten second ratio, same TIR test) so its R is fresnelExact's R; fresnelLiteral
// evaluates the slide's formula exactly as written, to show what the safe ordering fixes.
// Source: lecture "Reflection Math" (Cook & Torrance 1982, after Sparrow & Cess):
//   R = ½((g−c)/(g+c))²(1 + ((c(g+c) − m²)/(c(g−c) + m²))²), c = m cos θ, g = √(1 + c² − m²), m = nI/nT.
import { cosTransmittedSq } from '../../optics/fresnel.js';
import { checkCos, checkIndex, unit } from '../../optics/validate.js';

/**
 * g² = cos²θt = (1 − m²) + c², from fresnel.js's cosTransmittedSq: (nT² − nI² + (nI·cosθ)²)/nT²
 * with the numerator summed from exact products, so 1 + c² is never formed. Negative means total
 * internal reflection.
 */
export function gSquared(cosThetaI, nI, nT) {
  const ci = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  return cosTransmittedSq(ci, nI, nT);
}

/**
 * Every quantity of the formula: m, cos θ, c, g², g, a = (g−c)/(g+c), factor1 = a²,
 * b = (c(g+c) − m²)/(c(g−c) + m²), factor2 = 1 + b², and R = ½·factor1·factor2.
 * tir: g² ≤ 0, so g would be imaginary (g² < 0) and the code returns R = 1; g, a, b and the
 * factors are then NaN (undefined). matched: nI = nT, no interface, R = 0 at every angle.
 */
export function fresnelTerms(cosThetaI, nI, nT) {
  const cos = checkCos(cosThetaI);
  const m = nI / nT;
  const c = (nI * cos) / nT;
  const g2 = gSquared(cos, nI, nT);
  const matched = nI === nT;
  const tir = !matched && g2 <= 0;
  const base = { cos, m, c, g2, matched, tir };
  if (tir) return { ...base, g: g2 === 0 ? 0 : NaN, a: NaN, factor1: NaN, b: NaN, factor2: NaN, R: 1 };
  const g = Math.sqrt(g2);
  // c = 0 with m = 1 is 0/0 in the formula; matched media reflect nothing (fresnelExact returns 0).
  const a = matched && c === 0 ? 0 : (g - c) / (g + c);
  // The slide's ratio with c² − m² = −m²sin²θ substituted, as fresnel.js writes it: c(g+c) − m²
  // = cg − m²sin²θ and c(g−c) + m² = cg + m²sin²θ, with no difference of nearly equal terms.
  const ms2 = m * m * ((1 - cos) * (1 + cos));
  const cg = c * g;
  const b = (cg - ms2) / (cg + ms2);
  const factor1 = a * a;
  const factor2 = 1 + b * b;
  return { ...base, g, a, factor1, b, factor2, R: matched ? 0 : unit(0.5 * factor1 * factor2) };
}

/**
 * The slide's formula evaluated literally, left to right, with g² in one of two orders:
 * 'lecture' 1 + c² − m² (as on the slide) or 'safe' (1 − m)(1 + m) + c² (the factorisation
 * shaders/fresnel.glsl uses, here in m; fresnel.js forms g² exactly instead); like fresnel.js,
 * it adds c² to an index term that is exactly 0 for m = 1. With m = 1 and c below about 1e-8, c² is
 * under half an ulp of 1 (1.1e-16), so 1 + c² rounds to 1, the lecture order gives g² = 0, g = 0
 * and R = 1 instead of 0; the safe order keeps c².
 * g² < 0 takes the total-internal-reflection branch (R = 1), as any implementation must.
 */
export function fresnelLiteral(cosThetaI, nI, nT, order = 'lecture') {
  const cos = checkCos(cosThetaI);
  checkIndex(nI, 'nI');
  checkIndex(nT, 'nT');
  const m = nI / nT;
  const c = m * cos;
  const g2 = order === 'safe' ? (1 - m) * (1 + m) + c * c : 1 + c * c - m * m;
  if (g2 < 0) return { c, g2, R: 1 };
  const g = Math.sqrt(g2);
  const first = ((g - c) / (g + c)) ** 2;
  const second = 1 + ((c * (g + c) - m * m) / (c * (g - c) + m * m)) ** 2;
  return { c, g2, R: 0.5 * first * second };
}
