// The lecture's stone-skipping analogy, with how far it holds for the indices on show: its trend
// (the flatter the incidence, the more is reflected) holds at every angle, since unpolarized R
// rises monotonically from head-on to grazing (or to the critical angle); what needs a grazing
// angle is "mostly reflects" (R > 0.5). And reflection is not a bounce. Pure; every number comes
// from fresnel.js.
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
      ? `From the denser side R also grows with the angle, from ${R(0)} head-on, but it passes 0.5 at ${fixed(half, 1)}° `
        + `and reaches 1 at the critical angle, ${fixed(critical / DEG, 1)}°, far from grazing: the analogy does not describe that.`
      : `Its trend holds at every angle: R grows from ${R(0)} head-on to 1 at grazing. What needs a grazing angle is `
      + `"mostly reflects": light reflects more than it transmits only past ${fixed(half, 1)}° from the normal `
      + `(R = ${R(Math.floor(half / 10) * 10)} at ${Math.floor(half / 10) * 10}°, ${R(Math.min(89, Math.ceil(half) + 1))} at `
      + `${Math.min(89, Math.ceil(half) + 1)}°).`;
  return `The lecture likens this to skipping a stone: the flatter it meets the water, the more likely it skips. `
    + `${reach} And light is not a stone that bounces: R and T are how the wave's power divides at the interface.`;
}
