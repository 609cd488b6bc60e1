// @ts-check
// Questions on the Fresnel half of the lecture, in its order: materials and R(0°), polarisation
// and the Brewster angle, the exact formula, Schlick's approximation, Fresnel in lighting, metals,
// and where the methods fail or cost. Every expected answer comes from the optics core; see
// questions.js for the kinds.
import { cosDeg, toDegrees as deg } from '../optics/angles.js';
import { schlickErrorAt } from '../optics/curves.js';
import { displayCodes } from '../methods/advisor.js';
import { refinedMax } from '../optics/refinedMax.js';
import {
  brewsterAngle, criticalAngle, fresnelConductor, fresnelExact, fresnelPolarized, fresnelSchlick, normalIncidence,
} from '../optics/fresnel.js';
import { metals } from '../optics/materials.js';
import { methodError } from '../methods/advisor.js';
import { methodById } from '../methods/methods.js';
import { sceneById } from '../methods/scenes.js';
import { ANGLES, INDICES, degreesOf, dielectric, fixed, metal, number, numberList, question } from './questionParts.js';
import english from 'virtual:messages/en/questions';
import { messages } from '../i18n/messages.js';

// Every word a student reads is the catalogue's (locales/*.json, namespace questions: the
// question's id, then prompt, option.<id>, why.<id>, curve); `graded` is for engineers.
const t = messages('questions', english);

/** A hair above 1, as interpolated normals give; it survives rounding to float32 (1 + 2⁻²³). */
const COS_ABOVE_ONE = 1.0000001;
/**
 * Schlick's (pow form) largest display error in 8-bit codes for each index of the plastic scene, and
 * the angle of it: the best of a 0.05° grid, refined around it (refinedMax.js). Computed once.
 * @typedef {{ codes: number, theta: number, nT: number }} WorstCodes
 */
/** @type {WorstCodes[] | null} */
let worstPerIndex = null;
function schlickWorstPerIndex() {
  if (worstPerIndex) return worstPerIndex;
  const scene = sceneById('plastic');
  const method = methodById('schlick-pow');
  /** @type {(t: number, nI: number, nT: number) => number} */
  const codesAt = (t, nI, nT) => displayCodes(method.evaluate(scene.precision, cosDeg(t), nI, nT), fresnelExact(cosDeg(t), nI, nT));
  worstPerIndex = scene.cases.map(([nI, nT]) => {
    const theta = Array.from({ length: 1801 }, (_, i) => i / 20);
    const best = refinedMax(theta, theta.map((t) => codesAt(t, nI, nT)), (t) => codesAt(t, nI, nT));
    return { codes: best.value, theta: best.theta, nT };
  });
  return worstPerIndex;
}
/** The largest of them: Schlick's worst over the whole scene. */
const schlickWorstCodes = () => schlickWorstPerIndex().reduce((a, b) => (b.codes > a.codes ? b : a));
// Where an index's worst error sits below this angle, it is at middle angles rather than near grazing.
const MIDDLE_BELOW = 70;
/** Schlick's worst error in words' numbers: its codes, their share of the range, where; and, where the
 * worst sits at middle angles, from which index up and over which angles. */
function worstShown() {
  const { codes, theta, nT } = schlickWorstCodes();
  const all = schlickWorstPerIndex();
  const middle = all.filter((w) => w.theta < MIDDLE_BELOW);
  const from = Math.min(...middle.map((w) => w.nT));
  // The words say "from that index up": every index above it has its worst at middle angles too.
  if (!middle.length || all.some((w) => w.nT > from && w.theta >= MIDDLE_BELOW)) throw new RangeError('no single band of indices');
  return {
    codes: fixed(codes, 1), share: fixed((100 * codes) / 255, 1), theta: fixed(theta, 0), n: fixed(nT, 2),
    middleFrom: fixed(from, 2), middleLo: fixed(Math.min(...middle.map((w) => w.theta)), 0),
    middleHi: fixed(Math.max(...middle.map((w) => w.theta)), 0),
  };
}

/** The index whose R(0°) is the round 0.04 quoted for glass: ((1.5 − 1)/(1.5 + 1))² = 0.04. */
const ROUND_GLASS = 1.5;
/** Indices whose rims the rim-scaling explanation compares. */
const RIM_INDICES = [1.33, 1.5, 2];

export const FRESNEL_QUESTIONS = [
  question({
    id: 'r0-materials', panel: 'refractive-index', kind: 'choice',
    graded: 'R(0°) = ((n_t − n_i)/(n_t + n_i))² for water, N-BK7 crown glass and diamond from air: it grows with the index '
      + 'contrast (from air, with n_t) and is not 0.04 for all; 0.04 is its value for n = 1.5 exactly. The panel\'s material '
      + 'table lists n and R0 per material.',
    params: () => ({}),
    prompt: () => t('r0-materials.prompt'),
    options: () => {
      const r0 = (/** @type {string} */ id) => fixed(normalIncidence(1, dielectric(id).n), 3);
      const n = (/** @type {string} */ id) => fixed(dielectric(id).n, 3);
      const named = () => ({ water: r0('water'), glass: r0('glass'), diamond: r0('diamond'), nWater: n('water'), nGlass: n('glass'),
        nDiamond: n('diamond') });
      return [
        {
          id: 'all-004', text: () => t('r0-materials.option.all-004'),
          holds: () => ['water', 'glass', 'diamond'].every((id) => Math.abs(normalIncidence(1, dielectric(id).n) - 0.04) < 0.005),
          why: () => t('r0-materials.why.all-004', { ...named(), n: number(ROUND_GLASS), r0: fixed(normalIncidence(1, ROUND_GLASS), 3) }),
        },
        {
          id: 'depends-on-n', text: () => t('r0-materials.option.depends-on-n'),
          holds: () => normalIncidence(1, dielectric('water').n) < normalIncidence(1, dielectric('glass').n)
            && normalIncidence(1, dielectric('glass').n) < normalIncidence(1, dielectric('diamond').n),
          why: () => t('r0-materials.why.depends-on-n', named()),
        },
        {
          id: 'none-head-on', text: () => t('r0-materials.option.none-head-on'),
          holds: () => normalIncidence(1, dielectric('glass').n) === 0,
          why: () => t('r0-materials.why.none-head-on', named()),
        },
      ];
    },
    state: () => ({}),
  }),
  question({
    id: 'exact-rp-rs', panel: 'polarization', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: 'Rs − Rp of the s and p Fresnel equations from air into the given index at the given angle; the panel plots and '
      + 'reads out both.',
    params: (rng) => ({ theta: rng.pick(ANGLES), nT: rng.pick(INDICES) }),
    prompt: (p) => t('exact-rp-rs.prompt', { nT: number(p.nT), theta: number(p.theta) }),
    expected: (p) => {
      const { s, p: rp } = fresnelPolarized(cosDeg(p.theta), 1, p.nT);
      return s - rp;
    },
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'brewster-predict', panel: 'polarization', kind: 'predict', unit: 'deg', tolerance: 2,
    graded: 'Brewster\'s angle atan(n_t/n_i), where Rp = 0; the panel\'s plot marks Rp.',
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => t('brewster-predict.prompt', { nT: number(p.nT) }),
    expected: (p) => deg(brewsterAngle(1, p.nT)),
    curve: (p) => ({ label: t('brewster-predict.curve'), f: (t) => fresnelPolarized(cosDeg(t), 1, p.nT).p }),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'brewster-exact', panel: 'polarization', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'Brewster\'s angle atan(n_t/n_i) for the given pair; the panel marks and states it.',
    params: (rng) => ({ nI: rng.pick([1, 1.33]), nT: rng.pick([1.5, 1.6, 1.75, 2.42]) }),
    prompt: (p) => t('brewster-exact.prompt', { nI: number(p.nI), nT: number(p.nT) }),
    expected: (p) => deg(brewsterAngle(p.nI, p.nT)),
    state: (p) => ({ nI: p.nI, nT: p.nT }),
  }),
  question({
    id: 'exact-r', panel: 'exact-fresnel', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: 'The exact unpolarized reflectance (Rs + Rp)/2 at the given angle and index; the panel evaluates the lecture\'s '
      + 'formula term by term.',
    params: (rng) => ({ theta: rng.pick(ANGLES), nT: rng.pick(INDICES) }),
    prompt: (p) => t('exact-r.prompt', { theta: number(p.theta), nT: number(p.nT) }),
    expected: (p) => fresnelExact(cosDeg(p.theta), 1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'matched-grazing', panel: 'exact-fresnel', kind: 'choice',
    graded: 'R for equal indices on both sides, at 89.9°: 0, since no interface reflects; the panel\'s exact formula gives it at '
      + 'any angle.',
    params: (rng) => ({ n: rng.pick([1.33, 1.5, 2.42]) }),
    prompt: (p) => t('matched-grazing.prompt', { n: number(p.n) }),
    options: () => {
      const r = (/** @type {{ n: number }} */ p) => fresnelExact(cosDeg(89.9), p.n, p.n);
      /** @param {{ n: number }} p */
      const shown = (p) => ({ r: fixed(r(p), 3), n: number(p.n), fromAir: fixed(fresnelExact(cosDeg(89.9), 1, p.n), 3) });
      return [
        {
          id: 'one', text: () => t('matched-grazing.option.one'),
          holds: (p) => r(p) > 0.99,
          why: (p) => t('matched-grazing.why.one', shown(p)),
        },
        {
          id: 'zero', text: () => t('matched-grazing.option.zero'),
          holds: (p) => r(p) === 0,
          why: (p) => t('matched-grazing.why.zero', shown(p)),
        },
        {
          id: 'half', text: () => t('matched-grazing.option.half'),
          holds: (p) => Math.abs(r(p) - 0.5) < 0.05,
          why: (p) => t('matched-grazing.why.half', shown(p)),
        },
      ];
    },
    state: (p) => ({ nI: p.n, nT: p.n }),
  }),
  question({
    id: 'schlick-error', panel: 'schlick', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: '|exact R − Schlick| at the given angle and index; the panel plots both curves and their difference.',
    params: (rng) => ({ theta: rng.pick([60, 70, 75, 80, 85]), nT: rng.pick([1.33, 1.5, 2.0]) }),
    prompt: (p) => t('schlick-error.prompt', { nT: number(p.nT), theta: number(p.theta) }),
    expected: (p) => schlickErrorAt(p.theta, 1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'schlick-inside', panel: 'schlick', kind: 'choice',
    graded: 'From inside glass past the critical angle (41.8°) the exact R is 1 while Schlick on cos θ_i stays far below; the '
      + 'panel plots both from the denser side.',
    params: (rng) => ({ theta: rng.pick([45, 50, 60]) }),
    prompt: (p) => t('schlick-inside.prompt', { theta: number(p.theta) }),
    options: () => [
      {
        id: 'good', text: () => t('schlick-inside.option.good'),
        holds: (p) => Math.abs(fresnelExact(cosDeg(p.theta), 1.5, 1) - fresnelSchlick(cosDeg(p.theta), 1.5, 1)) < 0.05,
        why: (p) => t('schlick-inside.why.good', {
          critical: fixed(degreesOf(criticalAngle(1.5, 1)), 1), exact: fixed(fresnelExact(cosDeg(p.theta), 1.5, 1), 3),
          schlick: fixed(fresnelSchlick(cosDeg(p.theta), 1.5, 1), 3),
        }),
      },
      {
        id: 'misses-tir', text: () => t('schlick-inside.option.misses-tir'),
        holds: (p) => fresnelExact(cosDeg(p.theta), 1.5, 1) === 1 && fresnelSchlick(cosDeg(p.theta), 1.5, 1) < 0.9,
        why: (p) => t('schlick-inside.why.misses-tir', { schlick: fixed(fresnelSchlick(cosDeg(p.theta), 1.5, 1), 3) }),
      },
    ],
    state: () => ({ nI: 1.5, nT: 1 }),
  }),
  question({
    id: 'r0-value', panel: 'r0-derivation', kind: 'numeric', unit: 'fraction', tolerance: 0.00005,
    graded: 'R(0°) = ((n_t − n_i)/(n_t + n_i))² for the given index; the panel evaluates each step of the derivation.',
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => t('r0-value.prompt', { nT: number(p.nT) }),
    expected: (p) => normalIncidence(1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  }),
  question({
    id: 'rim-scaling', panel: 'fresnel-lighting', kind: 'choice',
    graded: 'Twice F(85°) for the given coat index exceeds 1, more light than arrives; the panel\'s plot gives F at every angle '
      + '(at its marked 80° twice F is still under 1: it passes 1 beyond about 83°, which is why the prompt names 85°).',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]) }),
    prompt: (p) => t('rim-scaling.prompt', { nT: number(p.nT) }),
    options: () => [
      {
        id: 'scale-up', text: () => t('rim-scaling.option.scale-up'),
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) <= 1,
        why: (p) => t('rim-scaling.why.scale-up', {
          rim: fixed(fresnelExact(cosDeg(85), 1, p.nT), 3), doubled: fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3),
          r0: fixed(normalIncidence(1, p.nT), 3),
        }),
      },
      {
        id: 'energy', text: () => t('rim-scaling.option.energy'),
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) > 1,
        why: (p) => t('rim-scaling.why.energy', {
          doubled: fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3),
          rims: numberList(RIM_INDICES.map((n) => fixed(fresnelExact(cosDeg(85), 1, n), 2))), indices: numberList(RIM_INDICES.map(number)),
        }),
      },
    ],
    state: (p) => ({ nT: p.nT }),
  }),
  question({
    id: 'metal-grazing', panel: 'metals', kind: 'choice',
    graded: 'The conductor reflectance per channel at 0° and 89° from the metal\'s n + ik: every channel approaches 1 and their '
      + 'spread shrinks; the panel\'s table, plot and spheres show it.',
    params: (rng) => ({ metal: rng.pick(['gold', 'copper']) }),
    prompt: (p) => t('metal-grazing.prompt', { metal: p.metal }),
    options: () => {
      /** @type {(p: { metal: string }, theta: number) => number[]} */
      const channels = (p, theta) => metal(p.metal).n.map((n, i) => fresnelConductor(cosDeg(theta), n, metal(p.metal).k[i]));
      const spread = (/** @type {number[]} */ rgb) => Math.max(...rgb) - Math.min(...rgb);
      const shown = (/** @type {number[]} */ rgb) => numberList(rgb.map((x) => fixed(x, 2)));
      return [
        {
          id: 'keeps-colour', text: () => t('metal-grazing.option.keeps-colour'),
          holds: (p) => spread(channels(p, 89)) >= spread(channels(p, 0)),
          why: (p) => t('metal-grazing.why.keeps-colour', { headOn: shown(channels(p, 0)), grazing: shown(channels(p, 89)) }),
        },
        {
          id: 'towards-white', text: () => t('metal-grazing.option.towards-white'),
          holds: (p) => Math.min(...channels(p, 89)) > 0.9 && spread(channels(p, 89)) < spread(channels(p, 0)),
          why: (p) => t('metal-grazing.why.towards-white', { grazing: shown(channels(p, 89)) }),
        },
        {
          id: 'dark', text: () => t('metal-grazing.option.dark'),
          holds: (p) => channels(p, 89).every((x, i) => x < channels(p, 0)[i]),
          why: (p) => {
            const [head, grazing] = [channels(p, 0), channels(p, 89)];
            const grows = grazing.every((x, i) => x > head[i]);
            return t('metal-grazing.why.dark', { grows: grows ? 'yes' : 'no', headOn: shown(head), grazing: shown(grazing) });
          },
        },
      ];
    },
    state: (p) => ({ metal: p.metal }),
  }),
  question({
    id: 'metal-r0', panel: 'metals', kind: 'numeric', unit: 'fraction', tolerance: 0.005,
    graded: 'A conductor\'s R(0°) = ((n − 1)² + k²)/((n + 1)² + k²) in the green channel; the panel\'s swatches and table give '
      + 'F0 per channel.',
    params: (rng) => ({ metal: rng.pick(metals.map((m) => m.id)) }),
    prompt: (p) => t('metal-r0.prompt', { nm: number(metal(p.metal).rgbNm[1]), metal: p.metal }),
    expected: (p) => fresnelConductor(1, metal(p.metal).n[1], metal(p.metal).k[1]),
    state: (p) => ({ metal: p.metal }),
  }),
  question({
    id: 'schlick-visible', panel: 'speed-accuracy', kind: 'choice',
    graded: 'The largest difference between Schlick and the exact R over the plastic scene (air into n from 1.3 to 1.7, every '
      + 'angle), in 8-bit sRGB codes at display white: a display choice, named in the prompt. The panel\'s table gives it '
      + 'per method.',
    params: () => ({}),
    prompt: () => t('schlick-visible.prompt'),
    options: () => [
      {
        id: 'invisible', text: () => t('schlick-visible.option.invisible'),
        holds: () => schlickWorstCodes().codes <= 0.5,
        why: () => t('schlick-visible.why.invisible', worstShown()),
      },
      {
        id: 'visible', text: () => t('schlick-visible.option.visible'),
        holds: () => schlickWorstCodes().codes > 2,
        why: () => {
          const exact = methodError(sceneById('plastic'), methodById('exact-cg')).maxCodes;
          const shown = { exactTiny: exact < 0.005 ? 'yes' : 'no', exactCodes: fixed(exact, 2) };
          return t('schlick-visible.why.visible', { ...worstShown(), ...shown });
        },
      },
    ],
    state: () => ({ scene: 'plastic' }),
  }),
  question({
    id: 'lecture-order', panel: 'shader-lab', kind: 'choice',
    graded: 'What the lecture\'s g = sqrt(1.0 + c*c − m*m) returns in float32 for matched indices near grazing: 1.0 + c*c rounds '
      + 'to 1.0 when c² is below 2⁻²⁴, so g = 0 and R = 1. The shader lab compiles the student\'s own version and grades '
      + 'this case.',
    params: (rng) => ({ n: rng.pick([1.33, 1.5]), theta: rng.pick([89.99, 89.999]) }),
    prompt: (p) => t('lecture-order.prompt', { n: number(p.n), theta: number(p.theta) }),
    options: () => {
      /** @param {{ n: number, theta: number }} p */
      const literal = (p) => methodById('exact-cg-literal').evaluate('fp32', cosDeg(p.theta), p.n, p.n);
      return [
        {
          id: 'zero', text: () => t('lecture-order.option.zero'),
          holds: (p) => literal(p) === 0,
          why: (p) => t('lecture-order.why.zero', { r: fixed(literal(p), 4) }),
        },
        {
          id: 'one', text: () => t('lecture-order.option.one'),
          holds: (p) => Math.abs(literal(p) - 1) < 1e-6,
          why: (p) => t('lecture-order.why.one', { r: fixed(literal(p), 4) }),
        },
        {
          id: 'nan', text: () => t('lecture-order.option.nan'),
          holds: (p) => Number.isNaN(literal(p)),
          why: (p) => t('lecture-order.why.nan', { r: fixed(literal(p), 4) }),
        },
      ];
    },
    state: () => ({ exercise: 'exact', homework: true }), // no reference answer: it would tell
  }),
  question({
    id: 'pow-above-one', panel: 'stability', kind: 'choice',
    graded: 'What pow(1 − cos θ, 5) is for cos θ a hair above 1 in a highp shader: 1 − cos θ is negative in float32, and GLSL ES '
      + '3.00 (§8.2) leaves pow undefined there. The stability map cannot show it (its θ = 0° column is cos θ = 1 exactly, '
      + 'classifyGrid.js columnCos), and the answer says so; the shader lab\'s "safe" exercise runs a student\'s code at such inputs.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]) }),
    prompt: (p) => t('pow-above-one.prompt', { cos: number(COS_ABOVE_ONE), nT: number(p.nT) }),
    options: () => {
      const value = (/** @type {{ nT: number }} */ p) => methodById('schlick-pow').evaluate('fp32', COS_ABOVE_ONE, 1, p.nT);
      const r0 = (/** @type {{ nT: number }} */ p) => normalIncidence(1, p.nT);
      return [
        {
          id: 'undefined', text: () => t('pow-above-one.option.undefined'),
          holds: (p) => !Number.isFinite(value(p)),
          why: () => t('pow-above-one.why.undefined'),
        },
        {
          id: 'r0', text: () => t('pow-above-one.option.r0'),
          holds: (p) => Number.isFinite(value(p)) && Math.abs(value(p) - r0(p)) < 1e-6,
          why: (p) => t('pow-above-one.why.r0', { r0: fixed(r0(p), 4) }),
        },
        {
          id: 'one', text: () => t('pow-above-one.option.one'),
          holds: (p) => value(p) === 1,
          why: () => t('pow-above-one.why.one'),
        },
      ];
    },
    state: () => ({ method: 'schlick-pow', precision: 'fp32' }),
  }),
];
