// Questions on the Fresnel half of the lecture, in its order: materials and R(0°), polarisation
// and the Brewster angle, the exact formula, Schlick's approximation, Fresnel in lighting, metals,
// and where the methods fail or cost. Every expected answer comes from the optics core; see
// questions.js for the kinds.
import { cosDeg, toDegrees as deg } from '../optics/angles.js';
import { schlickErrorAt } from '../optics/curves.js';
import { displayCodes } from '../methods/advisor.js';
import { goldenMax } from '../optics/refinedMax.js';
import {
  brewsterAngle, criticalAngle, fresnelConductor, fresnelExact, fresnelPolarized, fresnelSchlick, normalIncidence,
} from '../optics/fresnel.js';
import { dielectricById, metalById, metals } from '../optics/materials.js';
import { methodError } from '../methods/advisor.js';
import { methodById } from '../methods/methods.js';
import { sceneById } from '../methods/scenes.js';
import { ANGLES, INDICES, fixed } from './questionParts.js';

/** A hair above 1, as interpolated normals give; it survives rounding to float32 (1 + 2⁻²³). */
const COS_ABOVE_ONE = 1.0000001;
/**
 * Schlick's (pow form) largest display error over the plastic scene, in 8-bit codes: the best of a
 * 0.05° grid over each of the scene's indices, refined around it (refinedMax.js). Computed once.
 */
let worstCodes = null;
function schlickWorstCodes() {
  if (worstCodes) return worstCodes;
  const scene = sceneById('plastic');
  const method = methodById('schlick-pow');
  const codesAt = (t, nI, nT) => displayCodes(method.evaluate(scene.precision, cosDeg(t), nI, nT), fresnelExact(cosDeg(t), nI, nT));
  let best = { codes: -1, theta: 0, nI: 1, nT: 1 };
  for (const [nI, nT] of scene.cases) {
    for (let i = 0; i <= 1800; i += 1) {
      const codes = codesAt(i / 20, nI, nT);
      if (codes > best.codes) best = { codes, theta: i / 20, nI, nT };
    }
  }
  const { nI, nT } = best;
  const theta = goldenMax((t) => codesAt(t, nI, nT), Math.max(0, best.theta - 0.05), Math.min(90, best.theta + 0.05));
  const refined = codesAt(theta, nI, nT);
  worstCodes = refined > best.codes ? { codes: refined, theta, nI, nT } : best;
  return worstCodes;
}
const codesText = (codes) => (codes < 0.005 ? 'less than 0.01 codes' : `${fixed(codes, 2)} codes`);

/** Indices whose rims the rim-scaling explanation compares. */
const RIM_INDICES = [1.33, 1.5, 2];

export const FRESNEL_QUESTIONS = [
  {
    id: 'r0-materials', panel: 'refractive-index', kind: 'choice',
    graded: 'R(0°) = ((n_t − n_i)/(n_t + n_i))² for water, glass and diamond from air: it grows with the index and is not 0.04 '
      + 'for all. The panel\'s material table lists R0 per material.',
    params: () => ({}),
    prompt: () => 'Is R(0°) = 0.04 for every dielectric?',
    options: () => [
      {
        id: 'all-004', text: () => 'Yes: every dielectric reflects 4 % head-on.',
        holds: () => ['water', 'glass', 'diamond'].every((id) => Math.abs(normalIncidence(1, dielectricById(id).n) - 0.04) < 0.005),
        why: () => `No: 0.04 belongs to n = 1.5 (R(0°) = ${fixed(normalIncidence(1, 1.5), 3)}). `
          + `Water gives ${fixed(normalIncidence(1, dielectricById('water').n), 3)}, `
          + `diamond ${fixed(normalIncidence(1, dielectricById('diamond').n), 3)}.`,
      },
      {
        id: 'depends-on-n', text: () => 'No: it is ((n_t − n_i)/(n_t + n_i))², so it grows with the index.',
        holds: () => normalIncidence(1, dielectricById('water').n) < normalIncidence(1, dielectricById('glass').n)
          && normalIncidence(1, dielectricById('glass').n) < normalIncidence(1, dielectricById('diamond').n),
        why: () => `Right: water ${fixed(normalIncidence(1, dielectricById('water').n), 3)}, `
          + `glass ${fixed(normalIncidence(1, dielectricById('glass').n), 3)}, `
          + `diamond ${fixed(normalIncidence(1, dielectricById('diamond').n), 3)}.`,
      },
      {
        id: 'none-head-on', text: () => 'Nothing is reflected head-on: reflection needs a grazing angle.',
        holds: () => normalIncidence(1, dielectricById('glass').n) === 0,
        why: () => `No: head-on glass still reflects ${fixed(normalIncidence(1, dielectricById('glass').n), 3)}; `
          + `grazing only makes it more.`,
      },
    ],
    state: () => ({}),
  },
  {
    id: 'exact-rp-rs', panel: 'polarization', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: 'Rs − Rp of the s and p Fresnel equations from air into the given index at the given angle; the panel plots and '
      + 'reads out both.',
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
    graded: 'Brewster\'s angle atan(n_t/n_i), where Rp = 0; the panel\'s plot marks Rp.',
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => `From air into n_t = ${p.nT}: predict the angle at which R_p = 0 (within 2°), then look.`,
    expected: (p) => deg(brewsterAngle(1, p.nT)),
    curve: (p) => ({ label: 'Rₚ', f: (t) => fresnelPolarized(cosDeg(t), 1, p.nT).p }),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'brewster-exact', panel: 'polarization', kind: 'numeric', unit: 'deg', tolerance: 0.05,
    graded: 'Brewster\'s angle atan(n_t/n_i) for the given pair; the panel marks and states it.',
    params: (rng) => ({ nI: rng.pick([1, 1.33]), nT: rng.pick([1.5, 1.6, 1.75, 2.42]) }),
    prompt: (p) => `From n_i = ${p.nI} into n_t = ${p.nT}: the Brewster angle, in degrees to 0.1°.`,
    expected: (p) => deg(brewsterAngle(p.nI, p.nT)),
    state: (p) => ({ nI: p.nI, nT: p.nT }),
  },
  {
    id: 'exact-r', panel: 'exact-fresnel', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: 'The exact unpolarized reflectance (Rs + Rp)/2 at the given angle and index; the panel evaluates the lecture\'s '
      + 'formula term by term.',
    params: (rng) => ({ theta: rng.pick(ANGLES), nT: rng.pick(INDICES) }),
    prompt: (p) => `Light meets a surface from air at θ = ${p.theta}°, into n_t = ${p.nT}. `
      + `What fraction R is reflected (unpolarised)? To 3 decimals.`,
    expected: (p) => fresnelExact(cosDeg(p.theta), 1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'matched-grazing', panel: 'exact-fresnel', kind: 'choice',
    graded: 'R for equal indices on both sides, at 89.9°: 0, since no interface reflects; the panel\'s exact formula gives it at '
      + 'any angle.',
    params: (rng) => ({ n: rng.pick([1.33, 1.5, 2.42]) }),
    prompt: (p) => `Both sides of an interface have n = ${p.n} (n_i = n_t). `
      + `What does the exact formula give for R at θ = 89.9°, nearly grazing?`,
    options: () => {
      const r = (p) => fresnelExact(cosDeg(89.9), p.n, p.n);
      const fromAir = (p) => fixed(fresnelExact(cosDeg(89.9), 1, p.n), 3);
      return [
        {
          id: 'one', text: () => '1: at grazing every surface reflects everything.',
          holds: (p) => r(p) > 0.99,
          why: (p) => `No: with equal indices there is no interface to reflect from, and R = ${fixed(r(p), 3)} at every angle. `
            + `Grazing light is reflected strongly only where the indices differ: from air into ${p.n}, R(89.9°) = ${fromAir(p)}.`,
        },
        {
          id: 'zero', text: () => '0: nothing tells the two sides apart, so nothing is reflected.',
          holds: (p) => r(p) === 0,
          why: (p) => `Right: R = 0 at every angle, grazing included: `
            + `with nothing to tell the two sides apart there is no reflection (from air into ${p.n} it would be ${fromAir(p)}).`,
        },
        {
          id: 'half', text: () => 'About 0.5: at grazing the light splits evenly.',
          holds: (p) => Math.abs(r(p) - 0.5) < 0.05,
          why: (p) => `No: R = ${fixed(r(p), 3)}: with equal indices there is no interface, so nothing is split off.`,
        },
      ];
    },
    state: (p) => ({ nI: p.n, nT: p.n }),
  },
  {
    id: 'schlick-error', panel: 'schlick', kind: 'numeric', unit: 'fraction', tolerance: 0.0005,
    graded: '|exact R − Schlick| at the given angle and index; the panel plots both curves and their difference.',
    params: (rng) => ({ theta: rng.pick([60, 70, 75, 80, 85]), nT: rng.pick([1.33, 1.5, 2.0]) }),
    prompt: (p) => `From air into n_t = ${p.nT} at θ = ${p.theta}°: `
      + `how far is Schlick's approximation from the exact R (|exact − Schlick|)? To 3 decimals.`,
    expected: (p) => schlickErrorAt(p.theta, 1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'schlick-inside', panel: 'schlick', kind: 'choice',
    graded: 'From inside glass past the critical angle (41.8°) the exact R is 1 while Schlick on cos θ_i stays far below; the '
      + 'panel plots both from the denser side.',
    params: (rng) => ({ theta: rng.pick([45, 50, 60]) }),
    prompt: (p) => `Inside glass (n_i = 1.5) towards air at θ = ${p.theta}°, is Schlick's formula on cos θ_i a good estimate of R?`,
    options: () => [
      {
        id: 'good', text: () => 'Yes: Schlick works from either side.',
        holds: (p) => Math.abs(fresnelExact(cosDeg(p.theta), 1.5, 1) - fresnelSchlick(cosDeg(p.theta), 1.5, 1)) < 0.05,
        why: (p) => `No: past the critical angle (${fixed(deg(criticalAngle(1.5, 1)), 1)}°) `
          + `the exact R is ${fixed(fresnelExact(cosDeg(p.theta), 1.5, 1), 3)}, `
          + `Schlick on cos θ_i gives ${fixed(fresnelSchlick(cosDeg(p.theta), 1.5, 1), 3)}.`,
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
    id: 'r0-value', panel: 'r0-derivation', kind: 'numeric', unit: 'fraction', tolerance: 0.00005,
    graded: 'R(0°) = ((n_t − n_i)/(n_t + n_i))² for the given index; the panel evaluates each step of the derivation.',
    params: (rng) => ({ nT: rng.pick(INDICES) }),
    prompt: (p) => `R(0°), head-on, from air into n_t = ${p.nT}: to 4 decimals.`,
    expected: (p) => normalIncidence(1, p.nT),
    state: (p) => ({ nI: 1, nT: p.nT }),
  },
  {
    id: 'rim-scaling', panel: 'fresnel-lighting', kind: 'choice',
    graded: 'Twice F(85°) for the given coat index exceeds 1, more light than arrives; the panel\'s plot gives F at every angle '
      + '(at its marked 80° twice F is still under 1: it passes 1 beyond about 83°, which is why the prompt names 85°).',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]) }),
    prompt: (p) => `A coat of n = ${p.nT} looks too dull at the rim, where the view is about 85° from the surface normal. `
      + 'Should you scale F up (say ×2) to brighten it? Read F at 85° off the panel\'s plot.',
    options: () => [
      {
        id: 'scale-up', text: () => 'Yes: doubling F doubles the rim and keeps the centre right.',
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) <= 1,
        why: (p) => `No: F at 85° is already ${fixed(fresnelExact(cosDeg(85), 1, p.nT), 3)}; `
          + `doubled it is ${fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3)}, more light than arrives, `
          + `and the centre's ${fixed(normalIncidence(1, p.nT), 3)} doubles too.`,
      },
      {
        id: 'energy', text: () => 'No: F is a fraction of the light; scaled, it exceeds 1 near grazing and breaks energy conservation.',
        holds: (p) => 2 * fresnelExact(cosDeg(85), 1, p.nT) > 1,
        why: (p) => `Right: 2·F(85°) = ${fixed(2 * fresnelExact(cosDeg(85), 1, p.nT), 3)} > 1. `
          + `Brighten the light or the environment instead; `
          + `the index barely moves the rim (F(85°) = ${RIM_INDICES.map((n) => fixed(fresnelExact(cosDeg(85), 1, n), 2)).join(', ')} for `
          + `n = ${RIM_INDICES.join(', ')}).`,
      },
    ],
    state: (p) => ({ nT: p.nT }),
  },
  {
    id: 'metal-grazing', panel: 'metals', kind: 'choice',
    graded: 'The conductor reflectance per channel at 0° and 89° from the metal\'s n + ik: every channel approaches 1 and their '
      + 'spread shrinks; the panel\'s table, plot and spheres show it.',
    params: (rng) => ({ metal: rng.pick(['gold', 'copper']) }),
    prompt: (p) => `${metalById(p.metal).name} reflects its own colour head-on. What does it reflect at grazing incidence (89°)?`,
    options: () => {
      const channels = (p, theta) => metalById(p.metal).n.map((n, i) => fresnelConductor(cosDeg(theta), n, metalById(p.metal).k[i]));
      const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);
      return [
        {
          id: 'keeps-colour', text: () => 'The same colour, brighter: a metal keeps its colour at every angle.',
          holds: (p) => spread(channels(p, 89)) >= spread(channels(p, 0)),
          why: (p) => `No: head-on the channels are ${channels(p, 0).map((x) => fixed(x, 2)).join(', ')}; `
            + `at 89° they are ${channels(p, 89).map((x) => fixed(x, 2)).join(', ')}: nearly white.`,
        },
        {
          id: 'towards-white', text: () => 'Nearly white: every channel tends to 1 at grazing, so the tint fades.',
          holds: (p) => Math.min(...channels(p, 89)) > 0.9 && spread(channels(p, 89)) < spread(channels(p, 0)),
          why: (p) => `Right: at 89° the channels are ${channels(p, 89).map((x) => fixed(x, 2)).join(', ')}.`,
        },
        {
          id: 'dark', text: () => 'Dark: metals reflect less at grazing, as the diffuse light falls off.',
          holds: (p) => channels(p, 89).every((x, i) => x < channels(p, 0)[i]),
          why: (p) => {
            const [head, grazing] = [channels(p, 0), channels(p, 89)];
            const grows = grazing.every((x, i) => x > head[i]);
            return `No: ${grows ? 'every channel grows' : 'the channels go'} from ${head.map((x) => fixed(x, 2)).join(', ')} head-on to `
              + `${grazing.map((x) => fixed(x, 2)).join(', ')} at 89°.`;
          },
        },
      ];
    },
    state: (p) => ({ metal: p.metal }),
  },
  {
    id: 'metal-r0', panel: 'metals', kind: 'numeric', unit: 'fraction', tolerance: 0.005,
    graded: 'A conductor\'s R(0°) = ((n − 1)² + k²)/((n + 1)² + k²) in the green channel; the panel\'s swatches and table give '
      + 'F0 per channel.',
    params: (rng) => ({ metal: rng.pick(metals.map((m) => m.id)) }),
    prompt: (p) => `Head-on (0°), what fraction of green light (${metalById(p.metal).rgbNm[1]} nm) `
      + `does ${metalById(p.metal).name.toLowerCase()} reflect? To 2 decimals.`,
    expected: (p) => fresnelConductor(1, metalById(p.metal).n[1], metalById(p.metal).k[1]),
    state: (p) => ({ metal: p.metal }),
  },
  {
    id: 'schlick-visible', panel: 'speed-accuracy', kind: 'choice',
    graded: 'The largest difference between Schlick and the exact R over the plastic scene (air into n from 1.3 to 1.7, every '
      + 'angle), in 8-bit sRGB codes at display white: a display choice, named in the prompt. The panel\'s table gives it '
      + 'per method.',
    params: () => ({}),
    prompt: () => 'Light from air onto plastic, paint or skin (n from 1.3 to 1.7), at display white on an 8-bit sRGB screen: '
      + 'does Schlick’s pow(1 − c, 5) err by more than the display’s own rounding, half an 8-bit code, at any pixel?',
    options: () => {
      const where = () => {
        const { codes, theta, nT } = schlickWorstCodes();
        return `${fixed(codes, 1)} codes (${fixed((100 * codes) / 255, 1)} % of the range) at worst, `
          + `near θ = ${fixed(theta, 0)}° for n = ${fixed(nT, 2)}`;
      };
      return [
        {
          id: 'invisible', text: () => 'No: engines ship Schlick, so its error must stay within the display’s rounding.',
          holds: () => schlickWorstCodes().codes <= 0.5,
          why: () => `No: it is off by ${where()}. Engines accept an error of that size; that is a judgement about what `
            + 'viewers notice, not a property of the display.',
        },
        {
          id: 'visible', text: () => 'Yes: near grazing it is off by more than two codes at worst.',
          holds: () => schlickWorstCodes().codes > 2,
          why: () => `Right: ${where()}. The exact c/g form is off by `
            + `${codesText(methodError(sceneById('plastic'), methodById('exact-cg')).maxCodes)} at worst; `
            + `the panel weighs that against what each method costs on this device.`,
        },
      ];
    },
    state: () => ({ scene: 'plastic' }),
  },
  {
    id: 'lecture-order', panel: 'shader-lab', kind: 'choice',
    graded: 'What the lecture\'s g = sqrt(1.0 + c*c − m*m) returns in float32 for matched indices near grazing: 1.0 + c*c rounds '
      + 'to 1.0 when c² is below 2⁻²⁴, so g = 0 and R = 1. The shader lab compiles the student\'s own version and grades '
      + 'this case.',
    params: (rng) => ({ n: rng.pick([1.33, 1.5]), theta: rng.pick([89.99, 89.999]) }),
    prompt: (p) => `Both sides have n = ${p.n}. In float32 (highp), the lecture's code computes g = sqrt(1.0 + c*c - m*m) `
      + `at θ = ${p.theta}°. What R comes out?`,
    options: () => {
      const literal = (p) => methodById('exact-cg-literal').evaluate('fp32', cosDeg(p.theta), p.n, p.n);
      return [
        {
          id: 'zero', text: () => '0, as it must be with no interface.',
          holds: (p) => literal(p) === 0,
          why: (p) => `No: it gives ${fixed(literal(p), 4)}. With c² below half a float32 step of 1, 1.0 + c*c rounds to 1.0, `
            + `so g² = 0 and R = 1; (1 − m)(1 + m) + c² keeps c².`,
        },
        {
          id: 'one', text: () => '1: 1.0 + c*c rounds to 1.0, so g = 0 and the formula says everything is reflected.',
          holds: (p) => Math.abs(literal(p) - 1) < 1e-6,
          why: (p) => `Right: ${fixed(literal(p), 4)}, where the exact R is 0. `
            + `The grader's matched-indices criterion catches exactly this.`,
        },
        {
          id: 'nan', text: () => 'NaN: the square root of a negative number.',
          holds: (p) => Number.isNaN(literal(p)),
          why: (p) => `No: 1 + c² − m² is c² ≥ 0 in exact arithmetic and rounds to 0, not below; R comes out ${fixed(literal(p), 4)}.`,
        },
      ];
    },
    state: () => ({ exercise: 'exact', homework: true }), // no reference answer: it would tell
  },
  {
    id: 'pow-above-one', panel: 'stability', kind: 'choice',
    graded: 'What pow(1 − cos θ, 5) is for cos θ a hair above 1 in a highp shader: 1 − cos θ is negative in float32, and GLSL ES '
      + '3.00 (§8.2) leaves pow undefined there. The stability map shows the column at θ = 0°.',
    params: (rng) => ({ nT: rng.pick([1.33, 1.5]) }),
    prompt: (p) => `Interpolated normals can give cos θ = ${COS_ABOVE_ONE}, a hair above 1. In a highp shader, `
      + `what does Schlick's R0 + (1 − R0)·pow(1 − cos θ, 5) give there (from air into n_t = ${p.nT})?`,
    options: () => {
      const value = (p) => methodById('schlick-pow').evaluate('fp32', COS_ABOVE_ONE, 1, p.nT);
      const r0 = (p) => normalIncidence(1, p.nT);
      return [
        {
          id: 'undefined', text: () => 'Nothing usable: pow of a negative base is undefined in GLSL (NaN on many GPUs); '
            + 'clamp cos θ to [0, 1] first.',
          holds: (p) => !Number.isFinite(value(p)),
          why: () => 'Right: GLSL ES 3.00 (§8.2) leaves pow(x, y) undefined for x < 0, '
            + 'and log2 of a negative number is NaN where the GPU computes pow as exp2(y·log2 x). '
            + 'The stability map shows the column at θ = 0° for this method.',
        },
        {
          id: 'r0', text: () => 'R0, or a hair below it: (1 − cos θ)⁵ is a tiny negative number.',
          holds: (p) => Number.isFinite(value(p)) && Math.abs(value(p) - r0(p)) < 1e-6,
          why: (p) => `No: that is what float64 arithmetic with an odd power gives (R0 = ${fixed(r0(p), 4)}), `
            + `but a shader's pow of a negative base is undefined, and commonly NaN.`,
        },
        {
          id: 'one', text: () => '1: past its range the shader saturates.',
          holds: (p) => value(p) === 1,
          why: () => 'No: nothing saturates here; a negative base makes pow undefined, commonly NaN, which then spreads through the sum.',
        },
      ];
    },
    state: () => ({ method: 'schlick-pow', precision: 'fp32' }),
  },
];
