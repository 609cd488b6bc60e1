// Phong's highlight, with and without the Fresnel factor, in float64. Pure math, no DOM.
// Phong wrote the specular term as W(i)·cosⁿ(s), with W a reflectance that depends on the angle of
// incidence i (Bui Tuong Phong, "Illumination for Computer Generated Pictures", CACM 18(6), 1975);
// the usual form keeps only a constant k_s. The lecture's "Changing Specular" slides ask for the
// missing angle dependence: F(θ), θ the angle between the normal and the light (lecture, "Reflection
// Math"). Here k_s = R0 = F(0°), so both models agree head-on and differ only by what F adds.
import { fresnelExact, normalIncidence } from './fresnel.js';
import { DEG } from './angles.js';


/**
 * Phong's lobe (v·r)^s, 0 when the view is more than 90° from the mirror direction.
 * @param {number} vDotR
 * @param {number} s
 */
export function phongSpecular(vDotR, s) {
  if (!Number.isFinite(vDotR) || !(s >= 0)) throw new RangeError(`bad Phong arguments v·r = ${vDotR}, s = ${s}`);
  return Math.max(0, Math.min(1, vDotR)) ** s;
}

/**
 * Plain Phong with k_s = R0: R0·(v·r)^s, the same at every angle of incidence.
 * @param {number} vDotR
 * @param {number} s
 * @param {number} nI
 * @param {number} nT
 */
export function phongConstant(vDotR, s, nI, nT) {
  return normalIncidence(nI, nT) * phongSpecular(vDotR, s);
}

/**
 * Phong × F: F(θ)·(v·r)^s with F the exact unpolarized reflectance at cos θ = n·l.
 * @param {number} vDotR
 * @param {number} s
 * @param {number} cosThetaI
 * @param {number} nI
 * @param {number} nT
 */
export function phongFresnel(vDotR, s, cosThetaI, nI, nT) {
  return fresnelExact(cosThetaI, nI, nT) * phongSpecular(vDotR, s);
}

/**
 * cos of an elevation above the surface taken as an angle of incidence: cos(90° − e) = sin e.
 * @param {number} elevationDeg
 */
function incidenceCos(elevationDeg) {
  return elevationDeg >= 90 ? 1 : elevationDeg <= 0 ? 0 : Math.sin(elevationDeg * DEG);
}

/**
 * A cross-section through a flat surface (normal up) in the plane of incidence: the light at
 * elevation lightEl on one side, the viewer at elevation viewEl on the other (degrees above the
 * surface). The mirror direction r leaves at lightEl, so v·r = cos(viewEl − lightEl), and the
 * angle of incidence is θ = 90° − lightEl.
 * @param {number} lightElDeg
 * @param {number} viewElDeg
 */
export function phongGeometry(lightElDeg, viewElDeg) {
  return {
    vDotR: Math.cos((viewElDeg - lightElDeg) * DEG),
    cosThetaI: incidenceCos(lightElDeg),
    thetaDeg: 90 - lightElDeg,
  };
}

/**
 * Both highlights for one light and view: { vDotR, lobe, thetaDeg, F, R0, phong, phongF }.
 * @param {number} lightElDeg
 * @param {number} viewElDeg
 * @param {number} s
 * @param {number} nI
 * @param {number} nT
 */
export function phongHighlights(lightElDeg, viewElDeg, s, nI, nT) {
  const { vDotR, cosThetaI, thetaDeg } = phongGeometry(lightElDeg, viewElDeg);
  const lobe = phongSpecular(vDotR, s);
  const F = fresnelExact(cosThetaI, nI, nT);
  const R0 = normalIncidence(nI, nT);
  return { vDotR, lobe, thetaDeg, F, R0, phong: R0 * lobe, phongF: F * lobe };
}

/**
 * The peak of each highlight (view in the mirror direction, v·r = 1) against the elevation of the
 * light, from 0° (grazing) to 90° (overhead): plain Phong is R0 throughout, Phong × F is F(90° − e).
 * @param {number} nI
 * @param {number} nT
 */
export function peakHighlightCurves(nI, nT, count = 181) {
  const elevation = Array.from({ length: count }, (_, i) => (90 * i) / (count - 1));
  const phong = elevation.map(() => phongConstant(1, 1, nI, nT));
  const phongF = elevation.map((e) => phongFresnel(1, 1, incidenceCos(e), nI, nT));
  return { elevation, phong, phongF };
}
