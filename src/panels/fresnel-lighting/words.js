// @ts-check
// What the fresnel-lighting panel says of its two spheres, in the page's language: the weight of ks
// at the centre and at the rim, and whether the rim visibly turns toward ks (by one display code or
// more). Pure (no DOM), so tests/unit/fresnelLightingWords.test.js reads every case, the coat that
// reflects nothing included.
import english from 'virtual:messages/en/fresnel-lighting';
import { messages } from '../../i18n/messages.js';
import { cosDeg } from '../../optics/angles.js';
import { fresnelExact, fresnelSchlick } from '../../optics/fresnel.js';
import { angle, fixed } from '../../ui/format.js';
import { indexText } from '../shared/indexText.js';
import { hexToLinear, linearToSrgb } from '../../ui/srgb.js';

const t = messages('fresnel-lighting', english);
export const RIM_DEG = 80; // the angle quoted for the rim
const SHOWN = 4; // decimals of F in the panel's numbers and words
// Schlick's rim is said to overstate the coat where its F is this many times the exact one or more.
const OVERSTATED = 1.5;

/**
 * By how many display codes (8-bit sRGB, IEC 61966-2-1) the rim's colour mix(kd, ks, F) differs from
 * the base kd, in the channel where it differs most: under one, nothing visibly turns.
 * @param {number} F
 * @param {string} kd  '#rrggbb'
 * @param {string} ks  '#rrggbb'
 */
export function rimCodes(F, kd, ks) {
  const base = hexToLinear(kd);
  const coat = hexToLinear(ks);
  return Math.max(...base.map((b, i) => 255 * Math.abs(linearToSrgb(b + (coat[i] - b) * F) - linearToSrgb(b))));
}

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
 * What the Fresnel sphere's rim does: 'matched' where n_t = 1 and F = 0 at every angle; 'sameColour'
 * where kd and ks are one colour (within a display code), so the words cannot say the mix turns; 'none' where
 * F at the rim changes its colour by less than a display code (an index that near 1), so nothing
 * visibly turns; 'schlickNone' where Schlick's form turns the rim of a coat whose exact F would not
 * (its (1 − cos θ)⁵ does not vanish with R0); 'schlickOver' where it turns it much more than the exact
 * F would; 'turns' otherwise.
 * @param {{ nT: number, method: string, kd: string, ks: string }} values
 */
export function rimTrend({ nT, method, kd, ks }) {
  if (method !== 'schlick' && nT === 1) return 'matched';
  // kd and ks the same colour: no weight moves the mix of the two, only how each is lit does.
  if (rimCodes(1, kd, ks) < 1) return 'sameColour';
  const rim = weightAt(RIM_DEG, nT, method);
  if (rimCodes(rim, kd, ks) < 1) return 'none';
  if (method !== 'schlick') return 'turns';
  const exact = fresnelExact(cosDeg(RIM_DEG), 1, nT);
  if (rimCodes(exact, kd, ks) < 1) return 'schlickNone';
  return rim >= OVERSTATED * exact ? 'schlickOver' : 'turns';
}

/**
 * The panel's description of both spheres.
 * @param {{ nT: number, method: string, weight: number, kd: string, ks: string }} values
 * @param {number} ri  the share of diffuse light the coat's underside reflects back (physics.js coatConstants)
 */
export function describeSpheres(values, ri) {
  const { nT, method, weight } = values;
  return t('describe', {
    method, nT: indexText(nT), ri: fixed(ri, 3), f0: fixed(weightAt(0, nT, method), SHOWN),
    fRim: fixed(weightAt(RIM_DEG, nT, method), SHOWN), rim: angle(RIM_DEG, 0), w: fixed(weight, 3),
    trend: rimTrend(values), exactRim: fixed(fresnelExact(cosDeg(RIM_DEG), 1, nT), SHOWN), matched: nT === 1 ? 'yes' : 'no',
  });
}
