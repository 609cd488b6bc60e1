// The lecture's stone-skipping analogy, with how far it holds for the indices on show. The slide
// words it backwards (the greater the angle between the stone's velocity and the water's surface,
// the more skipping): a stone skips when it meets the water flat. Its trend (the flatter the
// incidence, the more is reflected) holds at every angle, since unpolarized R rises monotonically
// from head-on to grazing, or to the critical angle, for every index ratio below 2 + √3 ≈ 3.73
// (checked numerically in tests/unit/angle-ratio.test.js; above it R dips a little first), which
// covers every pair the panel offers. What needs a grazing angle is "mostly reflects" (R > 0.5).
// And reflection is not a bounce. Pure; every number comes from fresnel.js and physics.js.
import english from 'virtual:messages/en/angle-ratio';
import { messages } from '../../i18n/messages.js';
import { DEG, cosDeg } from '../../optics/angles.js';
import { criticalAngle, fresnelExact } from '../../optics/fresnel.js';
import { fixed, precise } from '../../ui/format.js';
import { halfReflectedAngle } from './physics.js';

const t = messages('angle-ratio', english);

/** The analogy's sentence for light from nI into nT. */
export function stoneAnalogy(nI, nT) {
  const half = halfReflectedAngle(nI, nT);
  const R = (t) => fixed(fresnelExact(cosDeg(t), nI, nT), 2);
  // Head-on R can be small (0.0035 from water into glass): two significant digits, never 0.00.
  const head = precise(fresnelExact(1, nI, nT), 2);
  const critical = criticalAngle(nI, nT);
  // R on either side of the half-way angle, to show it passing 0.5 (left out where that is within
  // two degrees of grazing, where no whole degree lies beyond it to show).
  const below = Math.floor(half / 10) * 10;
  const beyond = Math.ceil(half) + 1;
  // Two decimals where the two angles would print alike (nearly matched indices).
  const digits = critical !== null && half !== null && Math.abs(critical / DEG - half) < 0.1 ? 2 : 1;
  const reach = half === null ? 'equal' : critical !== null ? 'denser' : 'rarer';
  return t('stone', {
    reach,
    head,
    halfR: fixed(0.5, 1),
    half: half === null ? '' : fixed(half, critical !== null ? digits : 1),
    critical: critical === null ? '' : fixed(critical / DEG, digits),
    short: critical === null ? '' : fixed(90 - critical / DEG, 1),
    bracket: half !== null && beyond < 90 ? 'yes' : 'no',
    below: String(below),
    rBelow: R(below),
    beyond: String(beyond),
    rBeyond: R(beyond),
  });
}
