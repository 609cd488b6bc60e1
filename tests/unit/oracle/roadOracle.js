// The asphalt panel's road shaded from the textbook formulas with none of the lab's code: GGX D
// (Walter et al., EGSR 2007, eq. 33), height-correlated Smith G2 (Heitz, JCGT 3(2), 2014, eq. 99),
// Cook–Torrance, unpolarized Fresnel (Hecht, §4.6.2), Lambert, Rec. 709 luminance. The scene's
// constants are those the panel states: sun and sky light, albedo 0.09. y is up, z towards the sun.
import { fresnelR } from './rightAnswers.js';

const DEG = Math.PI / 180;
export const SUN = [3.6, 3.3, 2.9];
export const SKY = [0.16, 0.2, 0.27];
export const ALBEDO = 0.09;
export const luminance = (rgb) => 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];

/**
 * The BRDF's specular part for light l and view v (unit vectors from the road, y up), without E·cos θl.
 * @param {number[]} l
 * @param {number[]} v
 */
function specularBrdf(l, v, { roughness, nT, fresnel = true }) {
  const a2 = roughness ** 4; // α = roughness²
  const hRaw = l.map((x, i) => x + v[i]);
  const h = hRaw.map((x) => x / Math.hypot(...hRaw));
  const cosD = Math.min(1, l[0] * h[0] + l[1] * h[1] + l[2] * h[2]);
  const D = a2 / (Math.PI * (h[1] * h[1] * (a2 - 1) + 1) ** 2);
  const lambda = (c) => (Math.sqrt(1 + a2 * (1 / (c * c) - 1)) - 1) / 2;
  const G2 = 1 / (1 + lambda(l[1]) + lambda(v[1]));
  const F = fresnel ? fresnelR(Math.acos(cosD) / DEG, 1, nT) : ((nT - 1) / (nT + 1)) ** 2;
  return (D * G2 * F) / (4 * l[1] * v[1]);
}

export const sunVector = (sunEl) => [0, Math.sin(sunEl * DEG), Math.cos(sunEl * DEG)];

/**
 * Luminance of the sun's highlight and of the diffuse road seen along v (unit, from the road to the eye).
 * @param {number[]} v
 */
export function roadLight(v, { sunEl, roughness, nT, fresnel = true }) {
  const l = sunVector(sunEl);
  const E = luminance(SUN) * l[1];
  return {
    specular: specularBrdf(l, v, { roughness, nT, fresnel }) * E,
    diffuse: ALBEDO * (E / Math.PI + luminance(SKY)),
  };
}

/** The same for a spot straight towards the sun, seen belowDeg below the horizon. */
export const roadSpot = (belowDeg, values) => roadLight([0, Math.sin(belowDeg * DEG), -Math.cos(belowDeg * DEG)], values);

/**
 * The specular directional albedo ∫ f cos θo dωo by a midpoint sum over the outgoing hemisphere, in
 * cos θo and φ: the share of the sunlight the specular layer reflects.
 */
export function specularAlbedoByDirections({ sunEl, roughness, nT, fresnel = true }, n) {
  const l = sunVector(sunEl);
  let sum = 0;
  for (let i = 0; i < n; i += 1) {
    const mu = (i + 0.5) / n;
    const s = Math.sqrt(1 - mu * mu);
    for (let j = 0; j < 2 * n; j += 1) {
      const phi = (Math.PI * (j + 0.5)) / n;
      sum += specularBrdf(l, [s * Math.sin(phi), mu, s * Math.cos(phi)], { roughness, nT, fresnel }) * mu;
    }
  }
  return (sum * 2 * Math.PI) / (2 * n * n);
}
