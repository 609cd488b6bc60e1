// @ts-check
// Wrong answers worth a name, per numeric question: what a student gets by a known slip (R(0°) for
// R(θ), Schlick for exact, the complement of an angle, the wrong colour channel). Each is computed by
// the optics core from the student's own parameters, as the expected value is, so a class view can
// count how many made each slip although every student had other numbers. A factor that any question
// can show (×2, degrees converted twice) is labelled on the histogram instead (summarizeQuestions.js).
import { DEG, cosDeg, toDegrees as deg } from '../../optics/angles.js';
import {
  brewsterAngle, criticalAngle, fresnelConductor, fresnelExact, fresnelPolarized, fresnelSchlick, normalIncidence,
} from '../../optics/fresnel.js';
import { degreesOf, metal as metalOf } from '../questionParts.js';
import { toksvigFactor } from '../../normals/lobeFormulas.js';
import english from 'virtual:messages/en/questions';
import { messages } from '../../i18n/messages.js';

// A slip's label is the catalogue's (namespace questions, <question>.slip.<name>), in the language
// the class view is made in.
const t = messages('questions', english);

/** @typedef {{ label: string, value: number }} Slip */
/** @typedef {{ theta: number, nT: number }} AngleAndIndex */

// Each entry's function is written as a method of the type (`of`), so that it takes the shape of
// its own question's parameters, as the bank's questions do (questionParts.js).
/** @type {Record<string, { of(p: unknown): Slip[] }>} */
const SLIPS = {
  'exact-r': {
    of: (/** @type {AngleAndIndex} */ p) => [
      { label: t('exact-r.slip.r0'), value: normalIncidence(1, p.nT) },
      { label: t('exact-r.slip.transmitted'), value: 1 - fresnelExact(cosDeg(p.theta), 1, p.nT) },
      { label: t('exact-r.slip.schlick'), value: fresnelSchlick(cosDeg(p.theta), 1, p.nT) },
    ],
  },
  'exact-rp-rs': {
    of: (/** @type {AngleAndIndex} */ p) => {
      const { s, p: rp } = fresnelPolarized(cosDeg(p.theta), 1, p.nT);
      return [{ label: t('exact-rp-rs.slip.rsAlone'), value: s }, { label: t('exact-rp-rs.slip.swapped'), value: rp - s }];
    },
  },
  'r0-value': {
    of: (/** @type {{ nT: number }} */ p) => [
      { label: t('r0-value.slip.notSquared'), value: (p.nT - 1) / (p.nT + 1) },
      { label: t('r0-value.slip.always004'), value: 0.04 },
    ],
  },
  'brewster-exact': {
    of: (/** @type {{ nI: number, nT: number }} */ p) => [
      { label: t('brewster-exact.slip.complement'), value: 90 - deg(brewsterAngle(p.nI, p.nT)) },
    ],
  },
  'critical-angle': {
    of: (/** @type {{ nI: number }} */ p) => [
      { label: t('critical-angle.slip.complement'), value: 90 - degreesOf(criticalAngle(p.nI, 1)) },
    ],
  },
  'snell-angle': {
    of: (/** @type {AngleAndIndex} */ p) => {
      const swapped = Math.sin(p.theta * DEG) * p.nT;
      return [
        { label: t('snell-angle.slip.incidence'), value: p.theta },
        ...(swapped <= 1 ? [{ label: t('snell-angle.slip.swapped'), value: deg(Math.asin(swapped)) }] : []),
      ];
    },
  },
  'schlick-error': {
    of: (/** @type {AngleAndIndex} */ p) => [
      { label: t('schlick-error.slip.schlick'), value: fresnelSchlick(cosDeg(p.theta), 1, p.nT) },
      { label: t('schlick-error.slip.exact'), value: fresnelExact(cosDeg(p.theta), 1, p.nT) },
    ],
  },
  'split-half': {
    of: (/** @type {{ nT: number }} */ p) => [{ label: t('split-half.slip.brewster'), value: deg(brewsterAngle(1, p.nT)) }],
  },
  'metal-r0': {
    of: (/** @type {{ metal: string }} */ p) => {
      const metal = metalOf(p.metal);
      return [
        { label: t('metal-r0.slip.red'), value: fresnelConductor(1, metal.n[0], metal.k[0]) },
        { label: t('metal-r0.slip.blue'), value: fresnelConductor(1, metal.n[2], metal.k[2]) },
      ];
    },
  },
  'toksvig-exponent': {
    of: (/** @type {{ L: number, s: number }} */ p) => [
      { label: t('toksvig-exponent.slip.unchanged'), value: p.s },
      { label: t('toksvig-exponent.slip.factor'), value: toksvigFactor(p.L, p.s) },
    ],
  },
};

/**
 * The named slips of a question for these parameters ([] for a question without any).
 * @param {{ id: string }} question
 * @param {unknown} params  the question's, as its params() drew them
 * @returns {Slip[]}
 */
export function questionSlips(question, params) {
  return Object.hasOwn(SLIPS, question.id) ? SLIPS[question.id].of(params) : [];
}
