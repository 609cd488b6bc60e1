// @ts-check
// What the fresnel-lighting panel says of its two spheres, in the page's language: the weight of ks
// at the centre and at the rim, and whether the rim turns toward ks. Pure (no DOM), so
// tests/unit/fresnelLightingWords.test.js reads every case, the coat that reflects nothing included.
import english from 'virtual:messages/en/fresnel-lighting';
import { messages } from '../../i18n/messages.js';
import { cosDeg } from '../../optics/angles.js';
import { fresnelExact, fresnelSchlick } from '../../optics/fresnel.js';
import { angle, fixed } from '../../ui/format.js';
import { indexText } from '../shared/indexText.js';

const t = messages('fresnel-lighting', english);
export const RIM_DEG = 80; // the angle quoted for the rim
const SHOWN = 4; // decimals of F in the panel's numbers and words

/**
 * F at θ (degrees) on the Fresnel sphere, from the float64 reference (light from air into the coat):
 * Schlick's form where the panel shades with it, else the exact one (the layered coat too).
 * @param {number} thetaDeg
 * @param {number} nT
 * @param {string} method
 */
export function weightAt(thetaDeg, nT, method) {
  const c = cosDeg(thetaDeg);
  return method === 'schlick' ? fresnelSchlick(c, 1, nT) : fresnelExact(c, 1, nT);
}

/**
 * What the Fresnel sphere's rim does: 'matched' where n_t = 1 and F = 0 at every angle; 'none' where
 * F reads 0 at the shown decimals up to the rim (an index that near 1), so nothing visibly turns;
 * 'schlickNone' where Schlick's form still brightens the rim of a coat that reflects (next to) nothing,
 * its (1 − cos θ)⁵ not vanishing with R0; 'turns' otherwise.
 * @param {number} nT
 * @param {string} method
 */
export function rimTrend(nT, method) {
  const zero = fixed(0, SHOWN);
  if (method !== 'schlick' && nT === 1) return 'matched';
  if (fixed(weightAt(RIM_DEG, nT, method), SHOWN) === zero) return 'none';
  if (method === 'schlick' && fixed(fresnelExact(cosDeg(RIM_DEG), 1, nT), SHOWN) === zero) return 'schlickNone';
  return 'turns';
}

/**
 * The panel's description of both spheres.
 * @param {{ nT: number, method: string, weight: number }} values
 * @param {number} ri  the share of diffuse light the coat's underside reflects back (physics.js coatConstants)
 */
export function describeSpheres({ nT, method, weight }, ri) {
  return t('describe', {
    method, nT: indexText(nT), ri: fixed(ri, 3), f0: fixed(weightAt(0, nT, method), SHOWN),
    fRim: fixed(weightAt(RIM_DEG, nT, method), SHOWN), rim: angle(RIM_DEG, 0), w: fixed(weight, 3),
    trend: rimTrend(nT, method), exactRim: fixed(fresnelExact(cosDeg(RIM_DEG), 1, nT), SHOWN), matched: nT === 1 ? 'yes' : 'no',
  });
}
