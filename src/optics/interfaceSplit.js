// How one interface splits a ray's power: R reflected, T = 1 − R transmitted (energy is conserved
// in a lossless dielectric), and where the refracted ray goes. All values come from fresnel.js.
import { brewsterAngle, criticalAngle, fresnelExact, snellCosT } from './fresnel.js';
import { sampleAngles } from './curves.js';

const DEG = Math.PI / 180;

/** cos θ for θ in degrees, with cos 90° exactly 0 (Math.cos(π/2) is 6e-17 in float64). */
export function cosDeg(thetaDeg) {
  return thetaDeg >= 90 ? 0 : Math.cos(thetaDeg * DEG);
}

/**
 * The split at angle θ (degrees from the normal) from index n1 into n2:
 * { R, T, thetaT (degrees, null under total internal reflection), tir, critical, brewster }.
 * Past the critical angle (n1 > n2) there is no refracted ray: R = 1, T = 0 (Hecht, Optics §4.7).
 */
export function interfaceSplit(thetaDeg, n1, n2) {
  const cosI = cosDeg(thetaDeg);
  const R = fresnelExact(cosI, n1, n2);
  const cosT = snellCosT(cosI, n1, n2);
  const critical = criticalAngle(n1, n2);
  // At exactly the critical angle cos θt = 0: the ray would run along the surface carrying nothing.
  const tir = cosT === null || (critical !== null && cosT === 0);
  return {
    theta: thetaDeg,
    R,
    T: tir ? 0 : 1 - R,
    thetaT: tir ? null : Math.acos(Math.min(1, cosT)) / DEG,
    tir,
    critical: critical === null ? null : critical / DEG,
    brewster: brewsterAngle(n1, n2) / DEG,
  };
}

/** R and T against θ from 0° to 90° (the critical and Brewster angles included), for CSV export. */
export function interfaceSplitCurve(n1, n2, count = 181) {
  const theta = sampleAngles(n1, n2, count);
  const R = theta.map((t) => fresnelExact(cosDeg(t), n1, n2));
  return { theta, R, T: R.map((r) => 1 - r) };
}
