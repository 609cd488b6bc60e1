// @ts-check
// Wrong answers worth a name, per numeric question: what a student gets by a known slip (R(0°) for
// R(θ), Schlick for exact, the complement of an angle, the wrong colour channel). Each is computed by
// the optics core from the student's own parameters, as the expected value is, so a class view can
// count how many made each slip although every student had other numbers. A factor that any question
// can show (×2, degrees for radians) is labelled on the histogram instead (summarizeQuestions.js).
import { DEG, cosDeg, toDegrees as deg } from '../../optics/angles.js';
import {
  brewsterAngle, criticalAngle, fresnelConductor, fresnelExact, fresnelPolarized, fresnelSchlick, normalIncidence,
} from '../../optics/fresnel.js';
import { metalById } from '../../optics/materials.js';
import { toksvigFactor } from '../../normals/lobeFormulas.js';

/** @typedef {{ label: string, value: number }} Slip */

/** @type {Record<string, (p: any) => Slip[]>} */
const SLIPS = {
  'exact-r': (p) => [
    { label: 'R(0°), head-on, for R(θ)', value: normalIncidence(1, p.nT) },
    { label: 'the transmitted share 1 − R', value: 1 - fresnelExact(cosDeg(p.theta), 1, p.nT) },
    { label: 'Schlick’s approximation for the exact R', value: fresnelSchlick(cosDeg(p.theta), 1, p.nT) },
  ],
  'exact-rp-rs': (p) => {
    const { s, p: rp } = fresnelPolarized(cosDeg(p.theta), 1, p.nT);
    return [{ label: 'R_s alone', value: s }, { label: 'R_p − R_s, the wrong way round', value: rp - s }];
  },
  'r0-value': (p) => [
    { label: '(n − 1)/(n + 1), not squared', value: (p.nT - 1) / (p.nT + 1) },
    { label: '0.04, as if every material had it', value: 0.04 },
  ],
  'brewster-exact': (p) => [{ label: 'atan(n_i/n_t), the complement', value: 90 - deg(brewsterAngle(p.nI, p.nT)) }],
  'critical-angle': (p) => [{ label: 'acos for asin, the complement', value: 90 - deg(criticalAngle(p.nI, 1)) }],
  'snell-angle': (p) => {
    const swapped = Math.sin(p.theta * DEG) * p.nT;
    return [
      { label: 'the angle of incidence, not refracted', value: p.theta },
      ...(swapped <= 1 ? [{ label: 'n_i and n_t swapped', value: deg(Math.asin(swapped)) }] : []),
    ];
  },
  'schlick-error': (p) => [
    { label: 'Schlick’s R, not the difference', value: fresnelSchlick(cosDeg(p.theta), 1, p.nT) },
    { label: 'the exact R, not the difference', value: fresnelExact(cosDeg(p.theta), 1, p.nT) },
  ],
  'split-half': (p) => [{ label: 'the Brewster angle (R_p = 0), not R = ½', value: deg(brewsterAngle(1, p.nT)) }],
  'metal-r0': (p) => {
    const metal = metalById(p.metal);
    return [
      { label: 'the red channel for green', value: fresnelConductor(1, metal.n[0], metal.k[0]) },
      { label: 'the blue channel for green', value: fresnelConductor(1, metal.n[2], metal.k[2]) },
    ];
  },
  'toksvig-exponent': (p) => [
    { label: 'the exponent s unchanged', value: p.s },
    { label: 'Toksvig’s factor, not the exponent', value: toksvigFactor(p.L, p.s) },
  ],
};

/**
 * The named slips of a question for these parameters ([] for a question without any).
 * @param {{ id: string }} question
 * @param {any} params
 * @returns {Slip[]}
 */
export function questionSlips(question, params) {
  return Object.hasOwn(SLIPS, question.id) ? SLIPS[question.id](params) : [];
}
