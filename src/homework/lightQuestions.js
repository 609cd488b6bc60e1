// @ts-check
// Questions on the first half of the lecture, in its order: normal-map mips, grazing specular,
// Phong against Fresnel, reflection against refraction, waves at an interface, the angle ratio and
// the hero's exact-against-Schlick view. Every expected answer comes from the optics core; see
// questions.js for the kinds.
import { DEG, cosDeg } from '../optics/angles.js';
import { criticalAngle, fresnelExact } from '../optics/fresnel.js';
import { schlickErrorAt } from '../optics/curves.js';
import { phongHighlights } from '../optics/phong.js';
import { transmittedAngle } from '../optics/waves.js';
import { toksvigExponent, toksvigFactor } from '../normals/lobeFormulas.js';
import { INDICES, degreesOf, fixed, number, question } from './questionParts.js';
import { angleOfMax, angleWhere } from '../optics/solveAngle.js';
import { specularShareBelow } from '../panels/asphalt/physics.js';
import english from 'virtual:messages/en/questions';
import { messages } from '../i18n/messages.js';

// Every word a student reads is the catalogue's (locales/*.json, namespace questions: the
// question's id, then prompt, option.<id>, why.<id>, axis, curve); `graded` is for engineers.
const t = messages('questions', english);

/** @type {(nI: number, nT: number) => (thetaDeg: number) => number} */
const reflectance = (nI, nT) => (t) => fresnelExact(cosDeg(t), nI, nT);
/** @type {(nT: number) => (thetaDeg: number) => number} */
const schlickGap = (nT) => (t) => schlickErrorAt(t, 1, nT);
const ASPHALT_ROUGHNESS = 0.8;
// Measured with the panel's hover readout (angle to 0.1°, both parts to 3 decimals): where the shown parts
// are equal lies within 0.48° of the crossing for every parameter set (tests/unit/homeworkGraded.test.js).
const OUTSHINE_TOLERANCE = 0.5;
// A sun-ward spot of the asphalt panel's road, seen belowDeg below the horizon: the specular part's
// share of the light it sends towards the eye (0.5 where specular equals diffuse). On a flat road
// under a far sun and sky it depends on the direction alone, not on the camera or its framing.
/** @param {{ nT: number, sunEl: number }} p */
const specularShare = (p) => specularShareBelow({ sunEl: p.sunEl, roughness: ASPHALT_ROUGHNESS, nT: p.nT, fresnel: true });

export const LIGHT_QUESTIONS = [
  question({
    id: 'mip-renormalize', panel: 'normal-mips', kind: 'choice',
    graded: 'The length of the average of two unit normals tilted ±t, cos t < 1, and what renormalising it loses: the spread '
      + 'Toksvig reads from that shortfall. The panel\'s texel inspector shows the averaged normal\'s length and each '
      + 'technique\'s lobe.',
    params: (rng) => ({ tiltDeg: rng.pick([10, 20, 30]), s: rng.pick([32, 64, 128]) }),
    prompt: (p) => t('mip-renormalize.prompt', { tilt: number(p.tiltDeg) }),
    options: () => {
      // The average of two unit normals tilted ±t has length cos t; Toksvig reads the lost spread from it.
      const length = (/** @type {{ tiltDeg: number }} */ p) => Math.cos(p.tiltDeg * DEG);
      const shown = (/** @type {{ tiltDeg: number, s: number }} */ p) => ({
        length: fixed(length(p), 3), lowered: fixed(p.s * toksvigFactor(length(p), p.s), 1), s: number(p.s),
      });
      return [
        {
          id: 'keeps-roughness', text: () => t('mip-renormalize.option.keeps-roughness'),
          holds: (p) => toksvigFactor(length(p), p.s) === 1,
          why: (p) => t('mip-renormalize.why.keeps-roughness', shown(p)),
        },
        {
          id: 'loses-roughness', text: () => t('mip-renormalize.option.loses-roughness'),
          holds: (p) => length(p) < 1 && toksvigFactor(length(p), p.s) < 1,
          why: (p) => t('mip-renormalize.why.loses-roughness', shown(p)),
        },
      ];
    },
    state: () => ({}),
  }),
  question({
    id: 'toksvig-exponent', panel: 'normal-mips', kind: 'numeric', unit: null, tolerance: 0.5,
    graded: 'Toksvig\'s exponent s\' = s/(1 + s·σ²) with σ² = (1 − |N_a|)/|N_a|, from the two numbers given; the panel\'s '
      + 'Toksvig technique shows the same lowered lobe.',
    params: (rng) => ({ L: rng.pick([0.9, 0.95, 0.98, 0.99]), s: rng.pick([16, 32, 64, 128]) }),
    prompt: (p) => t('toksvig-exponent.prompt', { length: number(p.L), s: number(p.s) }),
    expected: (p) => toksvigExponent(p.L, p.s),
    state: () => ({ technique: 'toksvig' }),
  }),
  question({
    id: 'asphalt-outshine', panel: 'asphalt', kind: 'numeric', unit: 'deg', tolerance: OUTSHINE_TOLERANCE,
    graded: 'How far below the horizon a sun-ward spot of road is seen where the sun\'s highlight there is as bright as the diffuse '
      + 'road (lit by sun and sky; the panel leaves out the sky\'s own mirror image), measured with the panel\'s hover readout. '
      + 'It is a property of the panel\'s scene (its sun and sky light and its road\'s albedo set the diffuse part), which the '
      + 'prompt names as the panel\'s; on a flat road under a far sun and sky it depends on that direction alone, not on the '
      + 'camera or its field of view. The readout gives the angle to 0.1° and both parts to 3 decimals: every angle at which it '
      + 'shows the two parts equal lies within the tolerance of the crossing.',
    params: (rng) => ({ nT: rng.pick([1.5, 1.55, 1.6]), sunEl: rng.pick([10, 15, 20]) }),
    prompt: (p) => t('asphalt-outshine.prompt', {
      nT: number(p.nT), roughness: number(ASPHALT_ROUGHNESS), sunEl: number(p.sunEl), tolerance: number(OUTSHINE_TOLERANCE),
    }),
    expected: (p) => angleWhere(specularShare(p), 0.5, 0.5, 90),
    state: (p) => ({ nT: p.nT, sunEl: p.sunEl, roughness: ASPHALT_ROUGHNESS, camEl: 90, fresnel: true }),
  }),
  question({
    id: 'phong-grazing', panel: 'changing-specular', kind: 'choice',
    graded: 'The peak of the lecture\'s Phong highlight (v·r = 1, no n·l) with k_s = R0 against Phong × F, as the light drops '
      + 'from 90° to 5°: R0 stays, F(85°) grows many times. The panel\'s peak plot draws both against the elevation.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]), s: rng.pick([20, 60, 200]) }),
    prompt: (p) => t('phong-grazing.prompt', { nT: number(p.nT) }),
    options: () => {
      /** @type {(p: { s: number, nT: number }, model: 'phong' | 'phongF', elevation: number) => number} */
      const peak = (p, model, elevation) => phongHighlights(elevation, elevation, p.s, 1, p.nT)[model];
      const both = (/** @type {{ s: number, nT: number }} */ p) => ({
        phong90: fixed(peak(p, 'phong', 90), 3), phong5: fixed(peak(p, 'phong', 5), 3),
        fresnel90: fixed(peak(p, 'phongF', 90), 3), fresnel5: fixed(peak(p, 'phongF', 5), 3),
      });
      return [
        {
          id: 'fresnel-grows', text: () => t('phong-grazing.option.fresnel-grows'),
          holds: (p) => peak(p, 'phong', 5) === peak(p, 'phong', 90) && peak(p, 'phongF', 5) > 4 * peak(p, 'phongF', 90),
          why: (p) => t('phong-grazing.why.fresnel-grows', {
            ...both(p), growth: fixed((peak(p, 'phongF', 5) * Math.sin(5 * DEG)) / peak(p, 'phongF', 90), 1),
          }),
        },
        {
          id: 'both-grow', text: () => t('phong-grazing.option.both-grow'),
          holds: (p) => peak(p, 'phong', 5) > 1.01 * peak(p, 'phong', 90),
          why: (p) => t('phong-grazing.why.both-grow', both(p)),
        },
        {
          id: 'both-fade', text: () => t('phong-grazing.option.both-fade'),
          holds: (p) => peak(p, 'phongF', 5) < peak(p, 'phongF', 90),
          why: (p) => t('phong-grazing.why.both-fade', both(p)),
        },
      ];
    },
    state: (p) => ({ nT: p.nT, s: p.s, lightEl: 90, linked: true }),
  }),
  question({
    id: 'split-half', panel: 'reflect-refract', kind: 'numeric', unit: 'deg', tolerance: 0.5,
    graded: 'The angle of incidence from air where the exact unpolarized R is 0.5 for the given index; the panel\'s R and T bar '
      + 'and numbers follow the view angle.',
    params: (rng) => ({ nT: rng.pick([1.333, 1.45, 1.5, 1.6]) }),
    prompt: (p) => t('split-half.prompt', { nT: number(p.nT) }),
    expected: (p) => angleWhere(reflectance(1, p.nT), 0.5),
    state: (p) => ({ nT: p.nT }),
  }),
  question({
    id: 'snell-angle', panel: 'refraction-waves', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'The transmitted angle from Snell\'s law, asin(sin θ_i / n_t); the panel draws the refracted wavefronts and gives '
      + 'θ_t.',
    params: (rng) => ({ theta: rng.pick([20, 30, 40, 50, 60, 70]), nT: rng.pick(INDICES) }),
    prompt: (p) => t('snell-angle.prompt', { nT: number(p.nT), theta: number(p.theta) }),
    expected: (p) => degreesOf(transmittedAngle(p.theta * DEG, 1, p.nT)),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'critical-predict', panel: 'refraction-waves', kind: 'predict', unit: 'deg', tolerance: 2,
    graded: 'The critical angle asin(n_t/n_i) from inside the denser medium; the panel shows where the transmitted wave stops '
      + 'propagating.',
    params: (rng) => ({ nI: rng.pick([1.33, 1.5, 1.6, 2.42]) }),
    prompt: (p) => t('critical-predict.prompt', { nI: number(p.nI) }),
    expected: (p) => degreesOf(criticalAngle(p.nI, 1)),
    curve: (p) => ({ label: t('critical-predict.curve'), f: reflectance(p.nI, 1) }),
    state: (p) => ({ nI: p.nI, nT: 1 }),
  }),
  question({
    id: 'critical-angle', panel: 'angle-ratio', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'The critical angle asin(n_t/n_i); the panel\'s rays show T going to 0 there.',
    params: (rng) => ({ nI: rng.pick([1.33, 1.5, 1.6, 2.42]) }),
    prompt: (p) => t('critical-angle.prompt', { nI: number(p.nI) }),
    expected: (p) => degreesOf(criticalAngle(p.nI, 1)),
    state: (p) => ({ nI: p.nI, nT: 1 }),
  }),
  question({
    id: 'schlick-worst', panel: 'spheres', kind: 'predict', unit: 'deg', tolerance: 3,
    graded: 'The angle of incidence where |exact R − Schlick| is largest from air into the given index; the hero\'s error sphere '
      + 'and plot show it.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5, 1.75, 2.0]) }),
    prompt: (p) => t('schlick-worst.prompt', { nT: number(p.nT) }),
    expected: (p) => angleOfMax(schlickGap(p.nT)),
    curve: (p) => ({ label: t('schlick-worst.curve'), f: schlickGap(p.nT) }),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
];
