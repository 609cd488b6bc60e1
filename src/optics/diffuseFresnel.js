// The Fresnel reflectance of diffuse light: the cosine-weighted average of R over the hemisphere,
// r = 2∫₀¹ R(μ) μ dμ with μ = cos θ, the share of a Lambertian flux that an interface sends back
// (Egan & Hilgeman, Optical Properties of Inhomogeneous Materials, 1979; the "F_dr" of Jensen et
// al., SIGGRAPH 2001, §2.3). From inside a denser medium every μ below cos θc is totally reflected,
// so r is large: about 0.60 under a coat of n = 1.5, against 0.09 from the air above it. The two
// obey 1 − r_inside = (1 − r_outside)/n² (radiance scales with n²; a unit test checks it). Pure math.
import { criticalAngle, fresnelExact } from './fresnel.js';

/**
 * r = 2∫ R(μ) μ dμ for diffuse light in nI meeting nT. Past the critical angle R = 1 exactly, so
 * that part is (cos θc)²; the rest is integrated with μ = μc + (1 − μc)t², which removes the square
 * root R has at μc (and at 0 from outside), by composite Simpson's rule over t.
 */
export function hemisphericalReflectance(nI, nT, intervals = 2000) {
  const critical = criticalAngle(nI, nT);
  const muC = critical === null ? 0 : Math.cos(critical);
  const span = 1 - muC;
  const f = (t) => {
    const mu = muC + span * t * t;
    return fresnelExact(Math.min(1, mu), nI, nT) * mu * 2 * span * t;
  };
  let sum = f(0) + f(1);
  for (let i = 1; i < intervals; i += 1) sum += (i % 2 ? 4 : 2) * f(i / intervals);
  return muC * muC + (2 * sum) / (3 * intervals);
}
