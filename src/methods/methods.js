// The Fresnel methods the speed-accuracy panel compares, each written once with an arithmetic
// context (rounding.js) so it runs in float64, float32 or float16. Operations are in the order
// the GLSL twin evaluates them (left to right, as GLSL parses `a * b * c`); inputs are rounded
// to the precision first, as a uniform or varying would be. Outputs are not clamped unless the
// method as used in practice clamps (noted per method), so NaN and values outside [0, 1] can come
// out for the stability map to classify. Formulas: fresnel.js (sources there) and the source
// named at each method; cost hints: static SPIR-V instruction counts (computed: each method's
// GLSL through glslangValidator -V and spirv-opt -O, fp arithmetic, ext-inst, compare, select and
// branch instructions counted), with a rough ALU + SFU estimate alongside. A method's names are the
// catalogue's ("methods": method.<id>, methodShort.<id>), read when they are shown; its note, on how
// its cost was counted, is for whoever reads this table, not shown.
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';
import { conductorNormalIncidence, fresnelConductor } from '../optics/fresnel.js';
import { contextFor } from './rounding.js';

const t = messages('methods', english);

/** @typedef {import('./rounding.js').Context} Context */
/** @typedef {{ static: number, alu: number, sfu: number }} Cost  static: SPIR-V count; alu, sfu: a rough estimate */
/** @typedef {{ tirAware?: boolean, demonstratesFailure?: boolean, note: string }} MethodProps */
/** @typedef {(P: Context, ci: number, nI: number, nT: number) => number} DielectricBody */
/**
 * cpu: the float64 n, k and F0, for what the GPU gets as a uniform computed on the CPU.
 * @typedef {(P: Context, c: number, n: number, k: number, f0: number, cpu: { n: number, k: number, f0: number }) => number} ConductorBody
 */
/**
 * A Fresnel method. evaluate(precision, cos, ...case): a dielectric's case is nI, nT; a
 * conductor's n, k and optionally F0 (from n, k where it is left out).
 * @typedef {Readonly<MethodProps & {
 *   id: string, label: string, short: string, kind: 'dielectric' | 'conductor', cost: Cost,
 *   evaluate: (precision: unknown, cos: number, ...args: number[]) => number,
 * }>} Method
 */

/**
 * g² = cos²θt in fresnel.glsl's safe order: ((nT − nI)/nT)((nT + nI)/nT) + c², c = nI·ci/nT.
 * @param {Context} P
 * @param {number} ci
 * @param {number} nI
 * @param {number} nT
 */
function cosTransmittedSq(P, ci, nI, nT) {
  const c = P.div(P.mul(nI, ci), nT);
  return P.add(P.mul(P.div(P.sub(nT, nI), nT), P.div(P.add(nT, nI), nT)), P.mul(c, c));
}

/**
 * R0 = ((nT − nI)/(nT + nI))², computed in the shader from the two indices (fresnel.glsl).
 * @param {Context} P
 * @param {number} nI
 * @param {number} nT
 */
function normalIncidence(P, nI, nT) {
  const r = P.div(P.sub(nT, nI), P.add(nT, nI));
  return P.mul(r, r);
}

/**
 * R0 + (1 − R0)·x2·x2·x with x = 1 − c: Schlick by multiplications (Filament pow5).
 * @param {Context} P
 * @param {number} c
 * @param {number} r0
 */
function schlickMul(P, c, r0) {
  const x = P.sub(1, c);
  const x2 = P.mul(x, x);
  return P.add(r0, P.mul(P.sub(1, r0), P.mul(P.mul(x2, x2), x)));
}

/**
 * label: the method's name; short: a shorter one for crowded charts (both in the page's language).
 * @param {string} id
 * @param {Cost} cost
 * @param {MethodProps} props
 * @param {DielectricBody} body
 * @returns {Method}
 */
function dielectric(id, cost, props, body) {
  return {
    id,
    get label() { return t(`method.${id}`); },
    get short() { return t(`methodShort.${id}`); },
    kind: 'dielectric',
    cost,
    ...props,
    /** Reflectance for cos θi = cos, light going from index nI into nT. */
    evaluate(precision, cos, nI, nT) {
      const P = contextFor(precision);
      return body(P, P.round(cos), P.round(nI), P.round(nT));
    },
  };
}

/**
 * Exact c/g in fresnel.js's structure (safe g², c² − m² = −m²sin²θ), without its double-double.
 * @type {DielectricBody}
 */
function exactCg(P, ci, nI, nT) {
  if (nI === nT) return 0; // matched media: no interface (fresnel.js convention)
  const g2 = cosTransmittedSq(P, ci, nI, nT);
  if (g2 <= 0) return 1; // total internal reflection
  const g = P.sqrt(g2);
  const c = P.div(P.mul(nI, ci), nT);
  const a = P.div(P.sub(g, c), P.add(g, c));
  const m = P.div(nI, nT);
  const ms2 = P.mul(P.mul(m, m), P.mul(P.sub(1, ci), P.add(1, ci)));
  const cg = P.mul(c, g);
  const b = P.div(P.sub(cg, ms2), P.add(cg, ms2));
  return P.mul(P.mul(P.mul(0.5, a), a), P.add(1, P.mul(b, b)));
}

/**
 * The slide's c/g form as written: g² = 1 + c² − m² and B = (c(g+c) − m²)/(c(g−c) + m²).
 * 1 + c² rounds to 1 when c² is below half an ulp of 1, so matched media near grazing get
 * g² = 0 and R = 1 instead of 0 (computed with this model: for c < 1.05e-8 in float64 and
 * c < 2.44e-4 in float32). Same TIR branch as exact-cg; no
 * matched-media guard (the slide has none).
 * @type {DielectricBody}
 */
function exactCgLiteral(P, ci, nI, nT) {
  const m = P.div(nI, nT);
  const c = P.mul(m, ci);
  const g2 = P.sub(P.add(1, P.mul(c, c)), P.mul(m, m));
  if (g2 <= 0) return 1;
  const g = P.sqrt(g2);
  const a = P.div(P.sub(g, c), P.add(g, c));
  const b = P.div(P.sub(P.mul(c, P.add(g, c)), P.mul(m, m)), P.add(P.mul(c, P.sub(g, c)), P.mul(m, m)));
  return P.mul(P.mul(P.mul(0.5, a), a), P.add(1, P.mul(b, b)));
}

/**
 * s/p via Snell in pbrt-v4 FrDielectric's order (src/pbrt/util/scattering.h):
 * sin²θt = m²(1 − ci²), TIR if ≥ 1, ct = √(1 − sin²θt), rs = (m·ci − ct)/(m·ci + ct),
 * rp = (ci − m·ct)/(ci + m·ct). 1 − sin²θt cancels near the critical angle (computed with this model:
 * float16 is up to 0.16 off float64 for glass to air, at the critical angle, θ every 0.001°). Matched media return 0 as in
 * fresnel.js (pbrt-v4 returns 1 at grazing there: sin²θt = 1 takes its TIR branch).
 * @type {DielectricBody}
 */
function exactSp(P, ci, nI, nT) {
  if (nI === nT) return 0;
  const m = P.div(nI, nT);
  const s2t = P.mul(P.mul(m, m), P.sub(1, P.mul(ci, ci)));
  if (s2t >= 1) return 1;
  const ct = P.sqrt(P.sub(1, s2t));
  const mc = P.mul(m, ci);
  const rs = P.div(P.sub(mc, ct), P.add(mc, ct));
  const mct = P.mul(m, ct);
  const rp = P.div(P.sub(ci, mct), P.add(ci, mct));
  return P.mul(0.5, P.add(P.mul(rs, rs), P.mul(rp, rp)));
}

/**
 * Schlick 1994 with pow(1 − c, 5): NaN for c > 1 (pow of a negative base, undefined in GLSL ES 3.00 §8.2). No clamp.
 * @type {DielectricBody}
 */
function schlickPow(P, ci, nI, nT) {
  const r0 = normalIncidence(P, nI, nT);
  return P.add(r0, P.mul(P.sub(1, r0), P.pow(P.sub(1, ci), 5)));
}

/**
 * Schlick by multiplications only (Filament F_Schlick + pow5). No clamp; no TIR.
 * @type {DielectricBody}
 */
function schlickMulOnly(P, ci, nI, nT) {
  return schlickMul(P, ci, normalIncidence(P, nI, nT));
}

/**
 * Schlick on cos θt when nI > nT, 1 past the critical angle (fresnelSchlickTIR; Cycles).
 * @type {DielectricBody}
 */
function schlickTir(P, ci, nI, nT) {
  const r0 = normalIncidence(P, nI, nT);
  if (nI <= nT) return schlickMul(P, ci, r0);
  const g2 = cosTransmittedSq(P, ci, nI, nT);
  return g2 <= 0 ? 1 : schlickMul(P, P.sqrt(g2), r0);
}

/**
 * three.js F_Schlick (common.glsl.js, after Karis 2013): f = exp2((−5.55473c − 6.98316)c),
 * f0·(1 − f) + f90·f with f90 = 1. three.js saturates dotVH before the call, so c is clamped here.
 * @type {DielectricBody}
 */
function schlickExp2(P, ci, nI, nT) {
  const c = P.clamp(ci, 0, 1);
  const r0 = normalIncidence(P, nI, nT);
  const f = P.exp2(P.mul(P.sub(P.mul(P.round(-5.55473), c), P.round(6.98316)), c));
  return P.add(P.mul(r0, P.sub(1, f)), f);
}

/**
 * @param {string} id
 * @param {Cost} cost
 * @param {MethodProps} props
 * @param {ConductorBody} body
 * @returns {Method}
 */
function conductor(id, cost, props, body) {
  return {
    id,
    get label() { return t(`method.${id}`); },
    get short() { return t(`methodShort.${id}`); },
    kind: 'conductor',
    cost,
    ...props,
    /** Reflectance from air into n + ik; f0 is the per-channel F0 uniform (from n, k if omitted). */
    evaluate(precision, cos, n, k, f0 = conductorNormalIncidence(n, k)) {
      const P = contextFor(precision);
      return body(P, P.round(cos), P.round(n), P.round(k), P.round(f0), { n, k, f0 });
    },
  };
}

/**
 * Exact conductor in fresnel.glsl's order (Lagarde 2013 real form, stable a², b²), without its clamps.
 * @type {ConductorBody}
 */
function conductorExact(P, c, n, k) {
  const sin2 = P.mul(P.sub(1, c), P.add(1, c));
  const t0 = P.sub(P.sub(P.mul(n, n), P.mul(k, k)), sin2);
  const nk = P.mul(n, k);
  const S = P.sqrt(P.add(P.mul(t0, t0), P.mul(P.mul(4, nk), nk)));
  let a2;
  let b2;
  if (t0 >= 0) {
    a2 = P.mul(0.5, P.add(S, t0));
    b2 = a2 > 0 ? P.div(P.mul(nk, nk), a2) : 0;
  } else {
    b2 = P.mul(0.5, P.sub(S, t0));
    a2 = P.div(P.mul(nk, nk), b2);
  }
  const a = P.sqrt(a2);
  const dm = P.sub(a, c);
  const dp = P.add(a, c);
  const rsDen = P.add(P.mul(dp, dp), b2);
  if (rsDen <= 0) return 0;
  const rs = P.div(P.add(P.mul(dm, dm), b2), rsDen);
  if (rs <= 0) return 0;
  const um = P.sub(P.mul(a, c), sin2);
  const up = P.add(P.mul(a, c), sin2);
  const bc = P.mul(P.sqrt(b2), c);
  const rpDen = P.add(P.mul(up, up), P.mul(bc, bc));
  const rp = rpDen > 0 ? P.mul(rs, P.div(P.add(P.mul(um, um), P.mul(bc, bc)), rpDen)) : rs;
  return P.mul(0.5, P.add(rs, rp));
}

const MU_BAR = 1 / 7; // cos 81.8°, where F82 is specified (Hoffman 2019)

/**
 * F82-tint coefficients, computed once on the CPU in float64 (a uniform in practice).
 * Kutz et al., "Novel aspects of the Adobe Standard Material" (2021), after Hoffman, "Fresnel
 * equations considered harmful" (2019): F(c) = Schlick(c) − b·c(1 − c)^6,
 * b = (Schlick(1/7) − F82)/((1/7)(6/7)^6), F82 = tint·Schlick(1/7). The tint is chosen so F82 is
 * the exact conductor reflectance at cos = 1/7: the fit is then exact at 0°, ~82° and 90°.
 * @param {number} n
 * @param {number} k
 */
export function f82Coefficients(n, k, f0 = conductorNormalIncidence(n, k)) {
  const schlickBar = f0 + (1 - f0) * (1 - MU_BAR) ** 5;
  const f82 = fresnelConductor(MU_BAR, n, k);
  return { f0, f82, tint: f82 / schlickBar, b: (schlickBar - f82) / (MU_BAR * (1 - MU_BAR) ** 6) };
}

// b is a per-material constant (a uniform on the GPU), so it is computed once per (n, k, F0) and
// looked up by number keys: a string key would cost more than the method itself in the CPU timing.
/** @type {Map<number, Map<number, Map<number, number>>>} n → k → F0 → b */
const f82Cache = new Map();

/**
 * @param {number} n
 * @param {number} k
 * @param {number} f0
 */
function f82B(n, k, f0) {
  let byK = f82Cache.get(n);
  if (!byK) f82Cache.set(n, (byK = new Map()));
  let byF0 = byK.get(k);
  if (!byF0) byK.set(k, (byF0 = new Map()));
  let b = byF0.get(f0);
  if (b === undefined) byF0.set(f0, (b = f82Coefficients(n, k, f0).b));
  return b;
}

/**
 * F82-tint per channel: s = clamp(1 − c), clamp(F0 + (1 − F0)s⁵ − b·(c·s⁵·s)) (Cycles clamps, bsdf_util.h).
 * @type {ConductorBody}
 */
function conductorF82(P, c, _n, _k, f0, cpu) {
  const b = P.round(f82B(cpu.n, cpu.k, cpu.f0));
  const s = P.clamp(P.sub(1, c), 0, 1);
  const s2 = P.mul(s, s);
  const s5 = P.mul(P.mul(s2, s2), s);
  const schlick = P.add(f0, P.mul(P.sub(1, f0), s5));
  return P.clamp(P.sub(schlick, P.mul(b, P.mul(P.mul(c, s5), s))), 0, 1);
}

/** The method table. cost: static SPIR-V count (computed, see the top of the file); alu/sfu: rough estimate. */
export const METHODS = Object.freeze([
  dielectric('exact-cg', { static: 16, alu: 14, sfu: 3 },
    { tirAware: true, note: 'SPIR-V count: 8 fp-arith + 6 fma + 1 sqrt + 1 branch' }, exactCg),
  dielectric('exact-cg-literal', { static: 17, alu: 15, sfu: 3 },
    {
      tirAware: true,
      // Charted to show why the order matters; never recommended (it fails for matched media).
      demonstratesFailure: true,
      note: 'SPIR-V count + 1 add: 1 + c² − m² where the safe form adds c² to a precomputed 1 − m²',
    }, exactCgLiteral),
  dielectric('exact-sp', { static: 18, alu: 16, sfu: 3 },
    { tirAware: true, note: 'SPIR-V count: 9 fp-arith + 7 fma + 1 sqrt + 1 branch' }, exactSp),
  dielectric('schlick-pow', { static: 4, alu: 3, sfu: 2 },
    { tirAware: false, note: 'SPIR-V count: 2 fp-arith + 1 fma + 1 pow (pow = log2, mul, exp2)' }, schlickPow),
  dielectric('schlick-mul', { static: 6, alu: 5, sfu: 0 },
    { tirAware: false, note: 'SPIR-V count: 5 fp-arith + 1 fma' }, schlickMulOnly),
  dielectric('schlick-tir', { static: 14, alu: 10, sfu: 1 },
    { tirAware: true, note: 'SPIR-V count: 8 fp-arith + 3 fma + 1 sqrt + 2 branches' }, schlickTir),
  dielectric('schlick-exp2', { static: 5, alu: 3, sfu: 1 },
    { tirAware: false, note: 'SPIR-V count: 2 fp-arith + 2 fma + 1 exp2' }, schlickExp2),
  conductor('conductor-exact', { static: 32, alu: 20, sfu: 4 },
    { note: 'SPIR-V count: 26 fp-arith + 3 fma + 2 sqrt + 1 max (vec3)' }, conductorExact),
  conductor('conductor-schlick', { static: 6, alu: 5, sfu: 0 },
    { note: 'SPIR-V count: the multiplications-only Schlick on vec3 F0' },
    (P, c, _n, _k, f0) => schlickMul(P, c, f0)),
  conductor('conductor-f82', { static: 13, alu: 9, sfu: 0 },
    { note: 'SPIR-V count: 11 fp-arith + 2 clamp (vec3), b precomputed' }, conductorF82),
].map((method) => Object.freeze(method)));

const BY_ID = new Map(METHODS.map((m) => [m.id, m]));

export const METHOD_IDS = Object.freeze(METHODS.map((m) => m.id));

/**
 * The method with this id; throws on an unknown id.
 * @param {string} id
 */
export function methodById(id) {
  const method = BY_ID.get(id);
  if (!method) throw new RangeError(`unknown Fresnel method ${String(id)}`);
  return method;
}

/**
 * Methods of one kind, 'dielectric' or 'conductor', in table order.
 * @param {string} kind
 */
export function methodsOfKind(kind) {
  return METHODS.filter((m) => m.kind === kind);
}
