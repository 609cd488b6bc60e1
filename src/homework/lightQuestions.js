// Questions on the first half of the lecture, in its order: normal-map mips, grazing specular,
// Phong against Fresnel, reflection against refraction, waves at an interface, the angle ratio and
// the hero's exact-against-Schlick view. Every expected answer comes from the optics core; see
// questions.js for the kinds.
import { DEG, cosDeg, toDegrees as deg } from '../optics/angles.js';
import { criticalAngle, fresnelExact } from '../optics/fresnel.js';
import { schlickErrorAt } from '../optics/curves.js';
import { phongHighlights } from '../optics/phong.js';
import { transmittedAngle } from '../optics/waves.js';
import { toksvigExponent, toksvigFactor } from '../normals/lobeFormulas.js';
import { INDICES, fixed } from './questionParts.js';
import { angleOfMax, angleWhere } from '../optics/solveAngle.js';
import { specularShareBelow } from '../panels/asphalt/model.js';

const reflectance = (nI, nT) => (t) => fresnelExact(cosDeg(t), nI, nT);
const schlickGap = (nT) => (t) => schlickErrorAt(t, 1, nT);
const ASPHALT_ROUGHNESS = 0.8;
// A sun-ward spot of the asphalt panel's road, seen belowDeg below the horizon: the specular part's
// share of the light it sends towards the eye (0.5 where specular equals diffuse). On a flat road
// under a far sun and sky it depends on the direction alone, not on the camera or its framing.
const specularShare = (p) => specularShareBelow({ sunEl: p.sunEl, roughness: ASPHALT_ROUGHNESS, nT: p.nT, fresnel: true });

export const LIGHT_QUESTIONS = [
  {
    id: 'mip-renormalize', panel: 'normal-mips', kind: 'choice',
    graded: 'The length of the average of two unit normals tilted ±t, cos t < 1, and what renormalising it loses: the spread '
      + 'Toksvig reads from that shortfall. The panel\'s texel inspector shows the averaged normal\'s length and each '
      + 'technique\'s lobe.',
    params: (rng) => ({ tiltDeg: rng.pick([10, 20, 30]), s: rng.pick([32, 64, 128]) }),
    prompt: (p) => `Two normals tilted ±${p.tiltDeg}° are averaged into one texel of a coarser mip level. `
      + `Renormalising the average to length 1 keeps…`,
    options: () => {
      // The average of two unit normals tilted ±t has length cos t; Toksvig reads the lost spread from it.
      const length = (p) => Math.cos(p.tiltDeg * DEG);
      return [
        {
          id: 'keeps-roughness', text: () => '…the roughness: the direction is what matters.',
          holds: (p) => toksvigFactor(length(p), p.s) === 1,
          why: (p) => `No: the average has length ${fixed(length(p), 3)}; that shortfall is the spread of the normals. `
            + `Toksvig's factor turns it into a lower exponent (${fixed(p.s * toksvigFactor(length(p), p.s), 1)} instead of ${p.s}); `
            + `renormalised, the texel is as shiny as a flat one.`,
        },
        {
          id: 'loses-roughness', text: () => '…the direction only: the spread of the normals, and with it the roughness, is lost.',
          holds: (p) => length(p) < 1 && toksvigFactor(length(p), p.s) < 1,
          why: (p) => `Right: length ${fixed(length(p), 3)} carries the spread; `
            + `Toksvig's exponent ${fixed(p.s * toksvigFactor(length(p), p.s), 1)} instead of ${p.s} keeps the highlight as broad `
            + `as the bumps make it.`,
        },
      ];
    },
    state: () => ({}),
  },
  {
    id: 'toksvig-exponent', panel: 'normal-mips', kind: 'numeric', unit: null, tolerance: 0.5,
    graded: 'Toksvig\'s exponent s\' = s/(1 + s·σ²) with σ² = (1 − |N_a|)/|N_a|, from the two numbers given; the panel\'s '
      + 'Toksvig technique shows the same lowered lobe.',
    params: (rng) => ({ L: rng.pick([0.9, 0.95, 0.98, 0.99]), s: rng.pick([16, 32, 64, 128]) }),
    prompt: (p) => `A texel of a coarser mip level averages its normals into one of length |N_a| = ${p.L}. `
      + `Toksvig's formula lowers a Blinn-Phong exponent s = ${p.s} to what? To the nearest whole number (within 0.5).`,
    expected: (p) => toksvigExponent(p.L, p.s),
    state: () => ({ technique: 'toksvig' }),
  },
  {
    id: 'asphalt-outshine', panel: 'asphalt', kind: 'predict', unit: 'deg', tolerance: 2,
    graded: 'How far below the horizon a sun-ward spot of road is seen when the sun\'s highlight there is as bright as the diffuse '
      + 'road (lit by sun and sky; the panel, and the question, leave out the sky\'s own mirror image). On a flat road under a far '
      + 'sun and sky it depends on that direction alone, not on the camera or its field of view; the panel\'s hover readout gives '
      + 'each spot\'s angle below the horizon with both parts.',
    axis: 'Line of sight below the horizon',
    params: (rng) => ({ nT: rng.pick([1.5, 1.55, 1.6]), sunEl: rng.pick([10, 15, 20]) }),
    prompt: (p) => `A road of n_t = ${p.nT} and roughness ${ASPHALT_ROUGHNESS}, under a blue sky and a sun ${p.sunEl}° above it, `
      + `straight ahead. Look at spots of road straight towards the sun, from the spot below you (90° below the horizon) `
      + `towards the horizon. Predict how far below the horizon you are looking when the sun's highlight at a spot is first `
      + `as bright as the diffuse road there (lit by sun and sky; like the panel, leave out the sky's own mirror image in the `
      + `road). Lower the camera and hover the road: the readout gives each spot's angle below the horizon and both parts. `
      + `Within 2°.`,
    expected: (p) => angleWhere(specularShare(p), 0.5, 0.5, 90),
    curve: (p) => ({ label: 'Specular share of the light from the spot', f: specularShare(p), level: 0.5 }),
    state: (p) => ({ nT: p.nT, sunEl: p.sunEl, roughness: ASPHALT_ROUGHNESS, camEl: 90, fresnel: true }),
  },
  {
    id: 'phong-grazing', panel: 'changing-specular', kind: 'choice',
    graded: 'The peak of the lecture\'s Phong highlight (v·r = 1, no n·l) with k_s = R0 against Phong × F, as the light drops '
      + 'from 90° to 5°: R0 stays, F(85°) grows many times. The panel\'s peak plot draws both against the elevation.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]), s: rng.pick([20, 60, 200]) }),
    prompt: (p) => `Keep the viewer in the mirror direction and lower the light from overhead (90°) `
      + `to 5° above a surface of n_t = ${p.nT}. What happens to the peak of the highlight, in the lecture's Phong model `
      + `(the lobe (v·r)^s alone, with no n·l on the specular term)?`,
    options: () => {
      const peak = (p, model, elevation) => phongHighlights(elevation, elevation, p.s, 1, p.nT)[model];
      const both = (p) => `plain Phong ${fixed(peak(p, 'phong', 90), 3)} → ${fixed(peak(p, 'phong', 5), 3)}, `
        + `Phong × F ${fixed(peak(p, 'phongF', 90), 3)} → ${fixed(peak(p, 'phongF', 5), 3)}`;
      return [
        {
          id: 'fresnel-grows', text: () => 'Plain Phong (k_s = R0) stays the same; Phong × F grows many times over towards grazing.',
          holds: (p) => peak(p, 'phong', 5) === peak(p, 'phong', 90) && peak(p, 'phongF', 5) > 4 * peak(p, 'phongF', 90),
          why: (p) => `Right: ${both(p)}. In the mirror direction v·r = 1 at every elevation, so only F can tell grazing from overhead. `
            + `(A model that also weighs the specular term by n·l = sin 5° would see Phong × F grow only `
            + `×${fixed((peak(p, 'phongF', 5) * Math.sin(5 * DEG)) / peak(p, 'phongF', 90), 1)}; a microfacet BRDF `
            + 'also divides by cos θl cos θv, so its peak grows far more: see the asphalt panel.)',
        },
        {
          id: 'both-grow', text: () => 'Both grow: Phong’s lobe already brightens at grazing.',
          holds: (p) => peak(p, 'phong', 5) > 1.01 * peak(p, 'phong', 90),
          why: (p) => `No: ${both(p)}. (v·r)^s is 1 in the mirror direction whatever the elevation; `
            + `Phong ignores the angle between r and the surface.`,
        },
        {
          id: 'both-fade', text: () => 'Both fade: less light reaches a surface at grazing.',
          holds: (p) => peak(p, 'phongF', 5) < peak(p, 'phongF', 90),
          why: (p) => `No: ${both(p)}. The diffuse n·l fades at grazing; the reflected fraction F grows.`,
        },
      ];
    },
    state: (p) => ({ nT: p.nT, s: p.s, lightEl: 90, linked: true }),
  },
  {
    id: 'split-half', panel: 'reflect-refract', kind: 'numeric', unit: 'deg', tolerance: 0.5,
    graded: 'The angle of incidence from air where the exact unpolarized R is 0.5 for the given index; the panel\'s R and T bar '
      + 'and numbers follow the view angle.',
    params: (rng) => ({ nT: rng.pick([1.333, 1.45, 1.5, 1.6]) }),
    prompt: (p) => `A pool of n_t = ${p.nT} under an open sky. `
      + `At what angle from the normal does the surface reflect as much of the light as it transmits (R = T = 0.5)? In `
      + `degrees, within 0.5°.`,
    expected: (p) => angleWhere(reflectance(1, p.nT), 0.5),
    state: (p) => ({ nT: p.nT }),
  },
  {
    id: 'snell-angle', panel: 'refraction-waves', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'The transmitted angle from Snell\'s law, asin(sin θ_i / n_t); the panel draws the refracted wavefronts and gives '
      + 'θ_t.',
    params: (rng) => ({ theta: rng.pick([20, 30, 40, 50, 60, 70]), nT: rng.pick(INDICES) }),
    prompt: (p) => `A wave from air (n_i = 1) meets n_t = ${p.nT} at θ_i = ${p.theta}°. `
      + `At what angle θ_t from the normal does the transmitted wave travel? In degrees to 0.1°.`,
    expected: (p) => deg(transmittedAngle(p.theta * DEG, 1, p.nT)),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'critical-predict', panel: 'refraction-waves', kind: 'predict', unit: 'deg', tolerance: 2,
    graded: 'The critical angle asin(n_t/n_i) from inside the denser medium; the panel shows where the transmitted wave stops '
      + 'propagating.',
    params: (rng) => ({ nI: rng.pick([1.33, 1.5, 1.6, 2.42]) }),
    prompt: (p) => `A wave inside n_i = ${p.nI} meets air (n_t = 1). `
      + `Predict the angle of incidence past which no propagating transmitted wave leaves (within 2°), then look.`,
    expected: (p) => deg(criticalAngle(p.nI, 1)),
    curve: (p) => ({ label: 'R from inside', f: reflectance(p.nI, 1) }),
    state: (p) => ({ nI: p.nI, nT: 1 }),
  },
  {
    id: 'critical-angle', panel: 'angle-ratio', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'The critical angle asin(n_t/n_i); the panel\'s rays show T going to 0 there.',
    params: (rng) => ({ nI: rng.pick([1.33, 1.5, 1.6, 2.42]) }),
    prompt: (p) => `Light inside a medium of n_i = ${p.nI} meets air (n_t = 1). `
      + `Above what angle is all of it reflected? In degrees to 0.1°.`,
    expected: (p) => deg(criticalAngle(p.nI, 1)),
    state: (p) => ({ nI: p.nI, nT: 1 }),
  },
  {
    id: 'schlick-worst', panel: 'spheres', kind: 'predict', unit: 'deg', tolerance: 3,
    graded: 'The angle of incidence where |exact R − Schlick| is largest from air into the given index; the hero\'s error sphere '
      + 'and plot show it.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5, 1.75, 2.0]) }),
    prompt: (p) => `From air into n_t = ${p.nT}: predict the angle θ at which Schlick's approximation is furthest from the exact R (within `
      + `3°), then look at the error sphere and the plot.`,
    expected: (p) => angleOfMax(schlickGap(p.nT)),
    curve: (p) => ({ label: '|exact − Schlick|', f: schlickGap(p.nT) }),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
];
