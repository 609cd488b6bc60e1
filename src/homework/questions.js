// The homework questions, each on a panel of the lecture. Every expected answer is computed here by
// the float64 optics core (src/optics), never typed in: a numeric question gives its value and its
// tolerance; a choice question gives options whose truth the core decides (each wrong option comes
// with the explanation the panel shows). Parameters come from a seeded generator, so two students
// get different numbers and a seed gives the same ones back (seededRandom.js).
//   kind 'numeric': typed, with units, checked at the tolerance stated in the prompt;
//   kind 'predict': a value committed before the panel shows the truth (the prediction stays drawn);
//   kind 'choice':  one option holds.
import { DEG, cosDeg } from '../optics/angles.js';
import { brewsterAngle, criticalAngle, fresnelConductor, fresnelExact, fresnelPolarized, fresnelSchlick, normalIncidence } from '../optics/fresnel.js';
import { dielectricById, metalById, metals } from '../optics/materials.js';
import { toksvigFactor } from '../normals/lobeFormulas.js';

const INDICES = [1.33, 1.45, 1.5, 1.6, 1.75, 2.0, 2.42];
const ANGLES = [30, 40, 45, 50, 55, 60, 65, 70, 75, 80];
const fixed = (x, d) => x.toFixed(d);
const deg = (radians) => radians / DEG;

/** @typedef {{ id: string, text: (p: any) => string, holds: (p: any) => boolean, why: (p: any) => string }} ChoiceOption */

export const QUESTIONS = Object.freeze([
  {
    id: 'exact-r', panel: 'exact-fresnel', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    params: (rng) => ({ theta: rng.pick(ANGLES), nT: rng.pick(INDICES) }),
    prompt: (p) => `Light meets a surface from air at θ = ${p.theta}°, into n_t = ${p.nT}. What fraction R is reflected (unpolarised)? To 3 decimals.`,
    expected: (p) => fresnelExact(cosDeg(p.theta), 1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'exact-rp-rs', panel: 'polarization', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    params: (rng) => ({ theta: rng.pick(ANGLES), nT: rng.pick(INDICES) }),
    prompt: (p) => `From air into n_t = ${p.nT} at θ = ${p.theta}°: what is R_s − R_p? To 3 decimals.`,
    expected: (p) => {
      const { s, p: rp } = fresnelPolarized(cosDeg(p.theta), 1, p.nT);
      return s - rp;
    },
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'brewster-predict', panel: 'polarization', kind: 'predict', unit: 'deg', tolerance: 2,
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => `From air into n_t = ${p.nT}: predict the angle at which R_p = 0 (within 2°), then look.`,
    expected: (p) => deg(brewsterAngle(1, p.nT)),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'brewster-exact', panel: 'polarization', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    params: (rng) => ({ nI: rng.pick([1, 1.33]), nT: rng.pick([1.5, 1.6, 1.75, 2.42]) }),
    prompt: (p) => `From n_i = ${p.nI} into n_t = ${p.nT}: the Brewster angle, in degrees to 0.1°.`,
    expected: (p) => deg(brewsterAngle(p.nI, p.nT)),
    state: (p) => ({ nI: p.nI, nT: p.nT }),
  },
  {
    id: 'critical-angle', panel: 'angle-ratio', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    params: (rng) => ({ nI: rng.pick([1.33, 1.5, 1.6, 2.42]) }),
    prompt: (p) => `Light inside a medium of n_i = ${p.nI} meets air (n_t = 1). Above what angle is all of it reflected? In degrees to 0.1°.`,
    expected: (p) => deg(criticalAngle(p.nI, 1)),
    state: (p) => ({ nI: p.nI, nT: 1 }),
  },
  {
    id: 'r0-value', panel: 'r0-derivation', kind: 'numeric', unit: 'fraction', tolerance: 0.00005,
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => `R(0°), head-on, from air into n_t = ${p.nT}: to 4 decimals.`,
    expected: (p) => normalIncidence(1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'r0-materials', panel: 'refractive-index', kind: 'choice',
    params: () => ({}),
    prompt: () => 'Is R(0°) = 0.04 for every dielectric?',
    options: () => [
      {
        id: 'all-004', text: () => 'Yes: every dielectric reflects 4 % head-on.',
        holds: () => ['water', 'glass', 'diamond'].every((id) => Math.abs(normalIncidence(1, dielectricById(id).n) - 0.04) < 0.005),
        why: () => `No: 0.04 is glass's value (n ≈ 1.5). Water gives ${fixed(normalIncidence(1, dielectricById('water').n), 3)}, diamond ${fixed(normalIncidence(1, dielectricById('diamond').n), 3)}.`,
      },
      {
        id: 'depends-on-n', text: () => 'No: it is ((n_t − n_i)/(n_t + n_i))², so it grows with the index.',
        holds: () => normalIncidence(1, dielectricById('water').n) < normalIncidence(1, dielectricById('glass').n)
          && normalIncidence(1, dielectricById('glass').n) < normalIncidence(1, dielectricById('diamond').n),
        why: () => `Right: water ${fixed(normalIncidence(1, dielectricById('water').n), 3)}, glass ${fixed(normalIncidence(1, dielectricById('glass').n), 3)}, diamond ${fixed(normalIncidence(1, dielectricById('diamond').n), 3)}.`,
      },
      {
        id: 'none-head-on', text: () => 'Nothing is reflected head-on: reflection needs a grazing angle.',
        holds: () => normalIncidence(1, dielectricById('glass').n) === 0,
        why: () => `No: head-on glass still reflects ${fixed(normalIncidence(1, dielectricById('glass').n), 3)}; grazing only makes it more.`,
      },
    ],
    state: () => ({}),
  },
  {
    id: 'schlick-error', panel: 'schlick', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    params: (rng) => ({ theta: rng.pick([60, 70, 75, 80, 85]), nT: rng.pick([1.33, 1.5, 2.0]) }),
    prompt: (p) => `From air into n_t = ${p.nT} at θ = ${p.theta}°: how far is Schlick's approximation from the exact R (|exact − Schlick|)? To 3 decimals.`,
    expected: (p) => Math.abs(fresnelExact(cosDeg(p.theta), 1, p.nT) - fresnelSchlick(cosDeg(p.theta), 1, p.nT)),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'schlick-inside', panel: 'schlick', kind: 'choice',
    params: (rng) => ({ theta: rng.pick([45, 50, 60]) }),
    prompt: (p) => `Inside glass (n_i = 1.5) towards air at θ = ${p.theta}°, is Schlick's formula on cos θ_i a good estimate of R?`,
    options: () => [
      {
        id: 'good', text: () => 'Yes: Schlick works from either side.',
        holds: (p) => Math.abs(fresnelExact(cosDeg(p.theta), 1.5, 1) - fresnelSchlick(cosDeg(p.theta), 1.5, 1)) < 0.05,
        why: (p) => `No: past the critical angle (${fixed(deg(criticalAngle(1.5, 1)), 1)}°) the exact R is ${fixed(fresnelExact(cosDeg(p.theta), 1.5, 1), 3)}, Schlick on cos θ_i gives ${fixed(fresnelSchlick(cosDeg(p.theta), 1.5, 1), 3)}.`,
      },
      {
        id: 'misses-tir', text: () => 'No: it misses total internal reflection; it needs cos θ_t, and R = 1 past the critical angle.',
        holds: (p) => fresnelExact(cosDeg(p.theta), 1.5, 1) === 1 && fresnelSchlick(cosDeg(p.theta), 1.5, 1) < 0.9,
        why: (p) => `Right: the exact R is 1 here; Schlick on cos θ_i gives ${fixed(fresnelSchlick(cosDeg(p.theta), 1.5, 1), 3)}.`,
      },
    ],
    state: () => ({ nI: 1.5, nT: 1 }),
  },
  {
    id: 'metal-grazing', panel: 'metals', kind: 'choice',
    params: (rng) => ({ metal: rng.pick(['gold', 'copper']) }),
    prompt: (p) => `${metalById(p.metal).name} reflects its own colour head-on. What does it reflect at grazing incidence (89°)?`,
    options: () => {
      const channels = (p, theta) => metalById(p.metal).n.map((n, i) => fresnelConductor(cosDeg(theta), n, metalById(p.metal).k[i]));
      const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);
      return [
        {
          id: 'keeps-colour', text: () => 'The same colour, brighter: a metal keeps its colour at every angle.',
          holds: (p) => spread(channels(p, 89)) >= spread(channels(p, 0)),
          why: (p) => `No: head-on the channels are ${channels(p, 0).map((x) => fixed(x, 2)).join(', ')}; at 89° they are ${channels(p, 89).map((x) => fixed(x, 2)).join(', ')}: nearly white.`,
        },
        {
          id: 'towards-white', text: () => 'Nearly white: every channel tends to 1 at grazing, so the tint fades.',
          holds: (p) => Math.min(...channels(p, 89)) > 0.9 && spread(channels(p, 89)) < spread(channels(p, 0)),
          why: (p) => `Right: at 89° the channels are ${channels(p, 89).map((x) => fixed(x, 2)).join(', ')}.`,
        },
        {
          id: 'dark', text: () => 'Dark: metals reflect less at grazing, as the diffuse light falls off.',
          holds: (p) => Math.max(...channels(p, 89)) < Math.max(...channels(p, 0)),
          why: (p) => `No: every channel grows, to ${channels(p, 89).map((x) => fixed(x, 2)).join(', ')} at 89°.`,
        },
      ];
    },
    state: (p) => ({ metal: p.metal }),
  },
  {
    id: 'metal-r0', panel: 'metals', kind: 'numeric', unit: 'fraction', tolerance: 0.005,
    params: (rng) => ({ metal: rng.pick(metals.map((m) => m.id)) }),
    prompt: (p) => `Head-on (0°), what fraction of green light (${metalById(p.metal).rgbNm[1]} nm) does ${metalById(p.metal).name.toLowerCase()} reflect? To 2 decimals.`,
    expected: (p) => fresnelConductor(1, metalById(p.metal).n[1], metalById(p.metal).k[1]),
    state: (p) => ({ metal: p.metal }),
  },
  {
    id: 'rim-scaling', panel: 'fresnel-lighting', kind: 'choice',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]) }),
    prompt: (p) => `A coat of n = ${p.nT} looks too dull at the rim. Should you scale F up (say ×2) to brighten it?`,
    options: () => [
      {
        id: 'scale-up', text: () => 'Yes: doubling F doubles the rim and keeps the centre right.',
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) <= 1,
        why: (p) => `No: F at 85° is already ${fixed(fresnelExact(cosDeg(85), 1, p.nT), 3)}; doubled it is ${fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3)}, more light than arrives, and the centre's ${fixed(normalIncidence(1, p.nT), 3)} doubles too.`,
      },
      {
        id: 'energy', text: () => 'No: F is a fraction of the light; scaled, it exceeds 1 near grazing and breaks energy conservation.',
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) > 1,
        why: (p) => `Right: 2·F(85°) = ${fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3)} > 1. Change the light or the index instead.`,
      },
    ],
    state: (p) => ({ nT: p.nT }),
  },
  {
    id: 'mip-renormalize', panel: 'normal-mips', kind: 'choice',
    params: (rng) => ({ tiltDeg: rng.pick([10, 20, 30]), s: rng.pick([32, 64, 128]) }),
    prompt: (p) => `Two normals tilted ±${p.tiltDeg}° are averaged into one texel of a coarser mip level. Renormalising the average to length 1 keeps…`,
    options: () => {
      // The average of two unit normals tilted ±t has length cos t; Toksvig reads the lost spread from it.
      const length = (p) => Math.cos(p.tiltDeg * DEG);
      return [
        {
          id: 'keeps-roughness', text: () => '…the roughness: the direction is what matters.',
          holds: (p) => toksvigFactor(length(p), p.s) === 1,
          why: (p) => `No: the average has length ${fixed(length(p), 3)}; that shortfall is the spread of the normals. Toksvig's factor turns it into a lower exponent (${fixed(p.s * toksvigFactor(length(p), p.s), 1)} instead of ${p.s}); renormalised, the texel is as shiny as a flat one.`,
        },
        {
          id: 'loses-roughness', text: () => '…the direction only: the spread of the normals, and with it the roughness, is lost.',
          holds: (p) => length(p) < 1 && toksvigFactor(length(p), p.s) < 1,
          why: (p) => `Right: length ${fixed(length(p), 3)} carries the spread; Toksvig's exponent ${fixed(p.s * toksvigFactor(length(p), p.s), 1)} instead of ${p.s} keeps the highlight as broad as the bumps make it.`,
        },
      ];
    },
    state: () => ({}),
  },
]);

const byId = new Map(QUESTIONS.map((q) => [q.id, q]));

/** The question with this id, or undefined. */
export const questionById = (id) => byId.get(id);
