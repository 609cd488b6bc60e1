// @ts-check
// The exercises, each with its criteria stated before the student starts: which cases a criterion
// looks at, in which precision, and how close to the float64 core the function must come there.
// Tolerances are chosen so that a careful float32 implementation passes on any GPU (the lab's own
// GLSL twin stays within 2e-6 of the core away from the critical angle), and within 1° of the
// critical angle, where R is ill-conditioned and float32 cannot follow it, only sanity is asked
// (finite, in [0, 1]), except past it, where R = 1 is exact. Pure data: a criterion's words and an
// exercise's title are words.js's (the catalogue's "shader-lab": criterion.<id>, and the exercise
// control's options).
import { metalById } from '../../optics/materials.js';

/** @typedef {import('./gradingCases.js').GradingCase} GradingCase */

/**
 * A criterion: the precision it is graded in, what it compares with ('exact': the core's exact R,
 * 'schlick': Schlick's formula, 'sane': only finite and in [0, 1]), how close (none for 'sane'),
 * and which cases it looks at.
 * @typedef {object} Criterion
 * @property {string} id
 * @property {'highp' | 'mediump'} precision
 * @property {'exact' | 'schlick' | 'sane'} target
 * @property {number} [tolerance]
 * @property {(c: GradingCase) => boolean} select
 */

/**
 * An exercise: its kind ('dielectric': fresnel(cos, nI, nT); 'conductor': fresnelConductor(cos, n,
 * k) for its metal), its criteria's ids, a reference answer, the code it starts from, and the
 * signature the page calls.
 * @typedef {{ id: string, kind: 'dielectric' | 'conductor', metal?: string, criteria: string[], reference: string,
 *   start: string, signature: string }} Exercise
 */

const awayFromCritical = (c) => c.critical === null || Math.abs(c.thetaDeg - c.critical) >= 1;
const inRange = (c) => c.tag !== 'outside';

/** Criterion kinds: 'exact' compares with the core's exact R, 'schlick' with Schlick's formula. */
/** @type {Record<string, Omit<Criterion, 'id'>>} */
const CRITERIA = {
  schlickFromAir: {
    precision: 'highp', target: 'schlick', tolerance: 1e-5, select: (c) => c.family === 'fromAir' && inRange(c),
  },
  schlickClamped: {
    precision: 'highp', target: 'schlick', tolerance: 1e-5, select: (c) => c.tag === 'outside',
  },
  exactFromAir: {
    precision: 'highp', target: 'exact', tolerance: 1e-5, select: (c) => c.family === 'fromAir' && inRange(c),
  },
  // Nearly matched indices are ill-conditioned at grazing (float32 keeps R to about 1e-4 there);
  // the lecture's order fails by 1, not by 1e-3.
  matched: {
    precision: 'highp', target: 'exact', tolerance: 1e-3,
    select: (c) => (c.family === 'matched' || c.family === 'nearlyMatched') && inRange(c),
  },
  // From 0.001° past θc: closer, g² is below float32's rounding of the index terms on some GPUs.
  tir: {
    precision: 'highp', target: 'exact', tolerance: 1e-6,
    select: (c) => c.family === 'fromInside' && inRange(c) && c.thetaDeg - c.critical >= 1e-3,
  },
  fromInside: {
    precision: 'highp', target: 'exact', tolerance: 1e-4,
    select: (c) => c.family === 'fromInside' && inRange(c) && c.thetaDeg < c.critical && awayFromCritical(c),
  },
  nearCritical: {
    precision: 'highp', target: 'sane', select: (c) => c.critical !== null && inRange(c) && !awayFromCritical(c),
  },
  clamped: {
    precision: 'highp', target: 'exact', tolerance: 1e-5, select: (c) => c.tag === 'outside',
  },
  mediumpCritical: {
    precision: 'mediump', target: 'exact', tolerance: 0.01,
    select: (c) => c.family === 'fromInside' && c.tag === 'sweep' && c.critical - c.thetaDeg >= 1 && c.critical - c.thetaDeg <= 3,
  },
  mediumpSane: {
    precision: 'mediump', target: 'sane', select: inRange,
  },
  conductor: {
    precision: 'highp', target: 'exact', tolerance: 1e-4, select: inRange,
  },
  conductorClamped: {
    precision: 'highp', target: 'exact', tolerance: 1e-4, select: (c) => c.tag === 'outside',
  },
};

const DIELECTRIC_SIGNATURE = 'float fresnel(float cosTheta, float nI, float nT)';
const CONDUCTOR_SIGNATURE = 'vec3 fresnelConductor(float cosTheta, vec3 n, vec3 k)';

// Reference answers: what a student may be shown (never in homework mode). Each passes every
// criterion of its exercise (tests/e2e/panel-shader-lab.spec.js checks this on the GPU).
const SCHLICK = `// Schlick (1994): R0 + (1 − R0)(1 − cos θ)⁵, with cos θ clamped first.
float fresnel(float cosTheta, float nI, float nT) {
  float r = (nT - nI) / (nT + nI);
  float r0 = r * r;
  float x = 1.0 - clamp(cosTheta, 0.0, 1.0);
  float x2 = x * x;
  return r0 + (1.0 - r0) * x2 * x2 * x;
}`;

const EXACT = `// The exact unpolarised R in the lecture's c/g form, m = nI/nT, c = m·cos θ.
// g² = (1 − m)(1 + m) + c² (not 1 + c² − m², which loses c² near grazing).
float fresnel(float cosTheta, float nI, float nT) {
  if (nI == nT) return 0.0;            // no interface, no reflection
  float ci = clamp(cosTheta, 0.0, 1.0);
  float m = nI / nT;
  float c = m * ci;
  float g2 = (1.0 - m) * (1.0 + m) + c * c;
  if (g2 <= 0.0) return 1.0;           // total internal reflection
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float ms2 = m * m * (1.0 - ci) * (1.0 + ci);   // m² − c², without the cancellation
  float b = (c * g - ms2) / (c * g + ms2);
  return clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}`;

// highp inside: the index terms cancel near the critical angle, and mediump has only 11 bits for
// them. The parameters arrive in mediump, so they are copied to highp first: an operation takes
// the precision of its operands (GLSL ES 3.00 §4.5.2), not of the variable it is stored in.
const EXACT_MEDIUMP = `float fresnel(float cosTheta, float nI, float nT) {
  highp float hI = nI;
  highp float hT = nT;
  if (hI == hT) return 0.0;
  highp float ci = clamp(cosTheta, 0.0, 1.0);
  highp float m = hI / hT;
  highp float c = m * ci;
  highp float g2 = (1.0 - m) * (1.0 + m) + c * c;
  if (g2 <= 0.0) return 1.0;
  highp float g = sqrt(g2);
  highp float a = (g - c) / (g + c);
  highp float ms2 = m * m * (1.0 - ci) * (1.0 + ci);
  highp float b = (c * g - ms2) / (c * g + ms2);
  return clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}`;

const CONDUCTOR = `// Exact conductor R from air, complex index n + ik per channel (Born & Wolf §14.2;
// pbrt's FrConductor): a² + b² = √((n² − k² − sin²θ)² + 4n²k²), ab = nk. Of a² and b², the one
// whose formula does not cancel is computed first, the other from ab = nk.
vec3 fresnelConductor(float cosTheta, vec3 n, vec3 k) {
  float c = clamp(cosTheta, 0.0, 1.0);
  float s2 = (1.0 - c) * (1.0 + c);
  vec3 t0 = n * n - k * k - s2;
  vec3 nk2 = n * n * k * k;
  vec3 ab2 = sqrt(t0 * t0 + 4.0 * nk2);
  vec3 big = 0.5 * (ab2 + abs(t0));            // a² where t0 ≥ 0, b² where t0 < 0
  vec3 small = nk2 / max(big, 1e-30);
  vec3 up = step(0.0, t0);
  vec3 a = sqrt(mix(small, big, up));
  vec3 rs = (ab2 + c * c - 2.0 * a * c) / (ab2 + c * c + 2.0 * a * c);
  vec3 t1 = ab2 * c * c + s2 * s2;
  vec3 t2 = 2.0 * a * c * s2;
  vec3 rp = rs * (t1 - t2) / (t1 + t2);
  return clamp(0.5 * (rs + rp), 0.0, 1.0);
}`;

const START = `${DIELECTRIC_SIGNATURE} {
  // cosTheta: cos of the angle of incidence; nI, nT: the indices on each side.
  return 0.0;
}`;

/**
 * An exercise with the signature the page calls.
 * @param {Omit<Exercise, 'signature'>} exercise
 * @returns {Readonly<Exercise>}
 */
function withSignature(exercise) {
  return Object.freeze({ ...exercise, signature: exercise.kind === 'conductor' ? CONDUCTOR_SIGNATURE : DIELECTRIC_SIGNATURE });
}

/** @type {ReadonlyArray<Readonly<Exercise>>} */
export const EXERCISES = Object.freeze(/** @type {Array<Omit<Exercise, 'signature'>>} */ ([
  {
    id: 'schlick', kind: 'dielectric',
    criteria: ['schlickFromAir', 'schlickClamped'], reference: SCHLICK, start: START,
  },
  { id: 'exact', kind: 'dielectric', criteria: ['exactFromAir', 'matched'], reference: EXACT, start: START },
  {
    id: 'tir', kind: 'dielectric',
    criteria: ['exactFromAir', 'tir', 'fromInside', 'nearCritical'], reference: EXACT, start: START,
  },
  { id: 'safe', kind: 'dielectric', criteria: ['exactFromAir', 'clamped'], reference: EXACT, start: START },
  {
    id: 'mediump', kind: 'dielectric',
    criteria: ['mediumpCritical', 'mediumpSane', 'tir'], reference: EXACT_MEDIUMP, start: START,
  },
  {
    id: 'gold', kind: 'conductor', metal: 'gold',
    criteria: ['conductor', 'conductorClamped'], reference: CONDUCTOR,
    start: `${CONDUCTOR_SIGNATURE} {\n`
      + '  // n + ik: gold\'s complex index per channel (red 650 nm, green 550 nm, blue 450 nm).\n'
      + '  return vec3(0.0);\n}',
  },
]).map(withSignature));

export const EXERCISE_IDS = EXERCISES.map((e) => e.id);
export const exerciseById = (/** @type {string} */ id) => EXERCISES.find((e) => e.id === id);
/**
 * A criterion by its id.
 * @param {string} id
 * @returns {Criterion}
 */
export const criterion = (id) => ({ id, ...CRITERIA[id] });
/** The exact function for an exercise's kind: what the right-hand sphere is shaded with. */
export const exactReference = (/** @type {Exercise} */ exercise) => (exercise.kind === 'conductor' ? CONDUCTOR : EXACT);
export const exerciseMetal = (/** @type {Exercise} */ exercise) => (exercise.metal ? metalById(exercise.metal) : null);
