// The lecture's stone-skipping analogy, with how far it holds for the indices on show: light
// "mostly reflects" (R > 0.5) only close to grazing, and reflection is not a bounce. Pure; every
// number comes from fresnel.js.
import { DEG, cosDeg } from '../../optics/angles.js';
import { criticalAngle, fresnelExact } from '../../optics/fresnel.js';
import { angleWhere } from '../../optics/solveAngle.js';
import { fixed } from '../../ui/format.js';

/** θ where R = 1/2 (from 0° to 90°), or null when R never reaches it (equal indices). */
export function halfReflectedAngle(nI, nT) {
  const R = (t) => fresnelExact(cosDeg(t), nI, nT);
  return R(90) < 0.5 ? null : angleWhere(R, 0.5);
}

/** The analogy's sentence for light from nI into nT. */
export function stoneAnalogy(nI, nT) {
  const half = halfReflectedAngle(nI, nT);
  const R = (t) => fixed(fresnelExact(cosDeg(t), nI, nT), 2);
  const critical = criticalAngle(nI, nT);
  const reach = half === null
    ? 'With equal indices nothing is reflected at any angle.'
    : critical !== null
      ? `From the denser side light reflects more than it transmits past ${fixed(half, 1)}° and all of it past the `
        + `critical angle, ${fixed(critical / DEG, 1)}°, far from grazing: the analogy does not describe that.`
      : `Here light reflects more than it transmits only past ${fixed(half, 1)}° from the normal `
      + `(R = ${R(Math.floor(half / 10) * 10)} at ${Math.floor(half / 10) * 10}°, ${R(Math.min(89, Math.ceil(half) + 1))} at `
      + `${Math.min(89, Math.ceil(half) + 1)}°), so the analogy holds only that close to grazing.`;
  return `The lecture likens this to skipping a stone: the flatter it meets the water, the more likely it skips. `
    + `${reach} And light is not a stone that bounces: R and T are how the wave's power divides at the interface.`;
}
