// How one interface splits a ray's power: R reflected, T = 1 − R transmitted (energy is conserved
// in a lossless dielectric), and where the refracted ray goes. All values come from fresnel.js.
import { brewsterAngle, criticalAngle, fresnelExact, snellCosT } from '../../optics/fresnel.js';
import { sampleAngles } from '../../optics/curves.js';
import { cosDeg, DEG } from '../../optics/angles.js';
import { angleWhere } from '../../optics/solveAngle.js';


/**
 * The split at angle θ (degrees from the normal) from index n_i into n_t:
 * { R, T, thetaT (degrees, null under total internal reflection), tir, critical, brewster }.
 * Past the critical angle (n_i > n_t) there is no refracted ray: R = 1, T = 0 (Hecht, Optics §4.7).
 */
export function interfaceSplit(thetaDeg, nI, nT) {
  const cosI = cosDeg(thetaDeg);
  const R = fresnelExact(cosI, nI, nT);
  const cosT = snellCosT(cosI, nI, nT);
  const critical = criticalAngle(nI, nT);
  // At exactly the critical angle cos θt = 0: the ray would run along the surface carrying nothing.
  const tir = cosT === null || (critical !== null && cosT === 0);
  return {
    theta: thetaDeg,
    R,
    T: tir ? 0 : 1 - R,
    thetaT: tir ? null : Math.acos(Math.min(1, cosT)) / DEG,
    tir,
    critical: critical === null ? null : critical / DEG,
    brewster: brewsterAngle(nI, nT) / DEG,
  };
}

/** R and T against θ from 0° to 90° (the critical and Brewster angles included), for CSV export. */
export function interfaceSplitCurve(nI, nT, count = 181) {
  const theta = sampleAngles(nI, nT, count);
  const R = theta.map((t) => fresnelExact(cosDeg(t), nI, nT));
  return { theta, R, T: R.map((r) => 1 - r) };
}

/** θ where R = 1/2 (from 0° to 90°), or null when R never reaches it (equal indices). */
export function halfReflectedAngle(nI, nT) {
  const R = (t) => fresnelExact(cosDeg(t), nI, nT);
  return R(90) < 0.5 ? null : angleWhere(R, 0.5);
}
