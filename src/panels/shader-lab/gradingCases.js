// The inputs a student's Fresnel function is graded on, and what the float64 core says for each.
// The grid holds what breaks real implementations: total internal reflection, the critical angle
// ± tiny steps, grazing up to exactly 90°, cos θ a hair above 1 (interpolated normals) and below 0,
// and matched or nearly matched indices. Inputs are rounded to float32 first, as a uniform or a
// texture hands them to the GPU, and the reference is computed at those rounded inputs, so the
// comparison measures the student's arithmetic, not the rounding of the question. A case in words
// is words.js's (caseText).
import { DEG, cosDeg } from '../../optics/angles.js';
import { criticalAngle, fresnelConductor, fresnelExact, fresnelSchlick } from '../../optics/fresnel.js';

/** @typedef {'sweep' | 'grazing' | 'critical' | 'outside'} CaseTag */

/**
 * A dielectric case: cos θ, the indices, θ in degrees (null for cos outside [0, 1]), its family of
 * index pairs and its tag, θc in degrees (null without one), and the core's exact R and Schlick's.
 * @typedef {{ cos: number, nI: number, nT: number, thetaDeg: number | null, family: string, tag: CaseTag,
 *   critical: number | null, exact: number, schlick: number }} DielectricCase
 */

/**
 * A conductor case: cos θ, the metal's n and k per channel (red, green, blue), θ in degrees (null
 * for cos outside [0, 1]), its tag, no critical angle, and the core's exact R per channel.
 * @typedef {{ cos: number, n: number[], k: number[], thetaDeg: number | null, family: 'metal', tag: CaseTag,
 *   critical: null, exact: number[] }} ConductorCase
 */

/** @typedef {DielectricCase | ConductorCase} GradingCase */

const f = Math.fround;
const clamp01 = (x) => Math.min(1, Math.max(0, x));

/** Index pairs by family: light leaving air, light leaving a denser medium, matched, nearly matched. */
export const FAMILIES = Object.freeze({
  fromAir: [[1, 1.33], [1, 1.5], [1, 2.42]],
  fromInside: [[1.33, 1], [1.5, 1], [2.42, 1], [1.5, 1.33]],
  matched: [[1, 1], [1.5, 1.5], [1.333, 1.333]],
  nearlyMatched: [[1.5, 1.5001], [1.333, 1.3331]], // into the (barely) denser side: no critical angle, R ≈ 1e-9
});
const SWEEP = Array.from({ length: 181 }, (_, i) => i / 2); // 0° to 90° every 0.5°
const GRAZING = [89.9, 89.99, 89.999];
const CRITICAL_STEPS = [-1e-2, -1e-3, -1e-4, -1e-5, 1e-5, 1e-4, 1e-3, 1e-2]; // degrees from θc
const OUTSIDE = [1 + 1e-7, 1 + 1e-6, 1 + 1e-3, -1e-7, -1e-6, -1e-3]; // cos θ outside [0, 1]

/**
 * The dielectric cases: [{ cos, nI, nT, thetaDeg (null for cos outside [0, 1]), family, tag,
 * critical (θc in degrees or null), exact, schlick }] with tag 'sweep' | 'grazing' | 'critical' |
 * 'outside'. exact and schlick are the float64 core's at the float32 inputs, cos clamped to [0, 1]
 * as the core's contract does.
 * @returns {DielectricCase[]}
 */
export function dielectricCases() {
  const cases = [];
  const add = (cos, nI, nT, thetaDeg, family, tag) => {
    const c = f(cos);
    const [i, t] = [f(nI), f(nT)];
    const critical = criticalAngle(i, t);
    cases.push({
      cos: c, nI: i, nT: t, thetaDeg, family, tag, critical: critical === null ? null : critical / DEG,
      exact: fresnelExact(clamp01(c), i, t), schlick: fresnelSchlick(clamp01(c), i, t),
    });
  };
  for (const [family, pairs] of Object.entries(FAMILIES)) {
    for (const [nI, nT] of pairs) {
      for (const t of SWEEP) add(t === 90 ? 0 : cosDeg(t), nI, nT, t, family, 'sweep');
      for (const t of GRAZING) add(cosDeg(t), nI, nT, t, family, 'grazing');
      const critical = criticalAngle(nI, nT);
      if (critical !== null) {
        for (const d of CRITICAL_STEPS) add(Math.cos(critical + d * DEG), nI, nT, critical / DEG + d, family, 'critical');
      }
      if (family === 'fromAir' || family === 'fromInside') for (const c of OUTSIDE) add(c, nI, nT, null, family, 'outside');
    }
  }
  return cases;
}

/**
 * The conductor cases for one metal ({ n: [r, g, b], k: [r, g, b] }): θ sweep, grazing and cos outside [0, 1].
 * @returns {ConductorCase[]}
 */
export function conductorCases(metal) {
  const n = metal.n.map(f);
  const k = metal.k.map(f);
  const angles = [
    ...SWEEP.map((t) => [t === 90 ? 0 : cosDeg(t), t, 'sweep']),
    ...GRAZING.map((t) => [cosDeg(t), t, 'grazing']),
    ...OUTSIDE.map((c) => [c, null, 'outside']),
  ];
  return angles.map(([cos, thetaDeg, tag]) => {
    const c = f(cos);
    const exact = n.map((ni, ch) => fresnelConductor(clamp01(c), ni, k[ch]));
    return { cos: c, n, k, thetaDeg, tag, family: 'metal', critical: null, exact };
  });
}

/**
 * 4 floats per case for the GPU: (cos, nI, nT, 0) or (cos, n.rgb); extra: (k.rgb, 0) for conductors.
 * @param {GradingCase[]} cases
 */
export function caseInputs(cases) {
  const inputs = new Float32Array(cases.length * 4);
  const extra = new Float32Array(cases.length * 4);
  cases.forEach((c, i) => {
    if (c.n) {
      inputs.set([c.cos, ...c.n], i * 4);
      extra.set([...c.k, 0], i * 4);
    } else {
      inputs.set([c.cos, c.nI, c.nT, 0], i * 4);
    }
  });
  return { inputs, extra };
}
