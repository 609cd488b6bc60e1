// The Fresnel methods of src/optics/methods.js in GLSL ES 3.00, one function per method id
// ('exact-cg' → fm_exact_cg), with the same order of operations (GLSL parses `a * b * c` as
// (a * b) * c, as the JS nests its P.mul calls) and the same clamps: none unless the JS clamps.
// So NaN and values outside [0, 1] come out here exactly where the JS emulation predicts them.
// Sources and failure modes: methods.js.
//
// Precision: include after `precision highp float;` or `precision mediump float;`. Every float
// here takes that default, so the mediump variant is this same source compiled under mediump
// (float16 on GPUs that honour it; many desktop GPUs run it at float32).
// Helpers are prefixed fm_ so this file can sit beside <fresnel> in one program; the exact
// conductor shares fresnel.glsl's unclamped core.
//
// Dielectrics: fm_<id>(float c, float nI, float nT): c = cos θi, light from nI into nT.
// Conductors: fm_<id>(float c, float n, float k, float f0, float b): air into n + ik; f0 is the
// per-channel F0 uniform (conductorNormalIncidence(n, k) on the CPU), b the F82-tint coefficient
// (f82Coefficients(n, k, f0).b on the CPU); a method ignores what it does not use.
#include <fresnel>

// cos²θt and R0 are fresnel.glsl's cosTransmittedSq and normalIncidence (included above).

// R0 + (1 − R0)·x2·x2·x with x = 1 − c (Filament pow5).
float fm_schlickOn(float c, float r0) {
  float x = 1.0 - c;
  float x2 = x * x;
  return r0 + (1.0 - r0) * (x2 * x2 * x);
}

// 0: exact c/g, safe order (fresnel.glsl's fresnelExact without its clamps).
float fm_exact_cg(float ci, float nI, float nT) {
  return fresnelExactRaw(ci, nI, nT);
}

// 1: the slide's c/g as written, g² = 1 + c² − m²: 1 + c² rounds to 1 near grazing, so
// matched media get R = 1 instead of 0 there.
float fm_exact_cg_literal(float ci, float nI, float nT) {
  float m = nI / nT;
  float c = m * ci;
  float g2 = 1.0 + c * c - m * m;
  if (g2 <= 0.0) return 1.0;
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - m * m) / (c * (g - c) + m * m);
  return 0.5 * a * a * (1.0 + b * b);
}

// 2: s/p via Snell in pbrt-v4 FrDielectric's order; 1 − sin²θt cancels near θc.
float fm_exact_sp(float ci, float nI, float nT) {
  if (nI == nT) return 0.0;
  float m = nI / nT;
  float s2t = m * m * (1.0 - ci * ci);
  if (s2t >= 1.0) return 1.0;
  float ct = sqrt(1.0 - s2t);
  float mc = m * ci;
  float rs = (mc - ct) / (mc + ct);
  float mct = m * ct;
  float rp = (ci - mct) / (ci + mct);
  return 0.5 * (rs * rs + rp * rp);
}

// 3: Schlick with pow: undefined (NaN on most GPUs) for c > 1 (GLSL ES 3.00 §8.2).
float fm_schlick_pow(float ci, float nI, float nT) {
  float r0 = normalIncidence(nI, nT);
  return r0 + (1.0 - r0) * pow(1.0 - ci, 5.0);
}

// 4: Schlick by multiplications only; no TIR, no clamp.
float fm_schlick_mul(float ci, float nI, float nT) {
  return fm_schlickOn(ci, normalIncidence(nI, nT));
}

// 5: Schlick on cos θt when nI > nT, 1 past the critical angle.
float fm_schlick_tir(float ci, float nI, float nT) {
  float r0 = normalIncidence(nI, nT);
  if (nI <= nT) return fm_schlickOn(ci, r0);
  float g2 = cosTransmittedSq(ci, nI, nT);
  return g2 <= 0.0 ? 1.0 : fm_schlickOn(sqrt(g2), r0);
}

// 6: three.js F_Schlick (Karis 2013): f0·(1 − f) + f with f = exp2((−5.55473c − 6.98316)c), c saturated.
float fm_schlick_exp2(float ci, float nI, float nT) {
  float c = clamp(ci, 0.0, 1.0);
  float r0 = normalIncidence(nI, nT);
  float f = exp2((-5.55473 * c - 6.98316) * c);
  return r0 * (1.0 - f) + f;
}

// 7: exact conductor (Lagarde 2013 real form, stable a², b²) without fresnel.glsl's clamps.
float fm_conductor_exact(float c, float n, float k, float f0, float b) {
  vec2 sp = conductorPolarizedRaw(c, n, k); // shared with fresnel.glsl, which clamps around it
  return 0.5 * (sp.x + sp.y);
}

// 8: Schlick with the per-channel F0.
float fm_conductor_schlick(float c, float n, float k, float f0, float b) {
  return fm_schlickOn(c, f0);
}

// 9: F82-tint (Hoffman 2019; Kutz et al. 2021): clamp(F0 + (1 − F0)s⁵ − b·c·s⁵·s), s = clamp(1 − c).
float fm_conductor_f82(float c, float n, float k, float f0, float b) {
  float s = clamp(1.0 - c, 0.0, 1.0);
  float s2 = s * s;
  float s5 = s2 * s2 * s;
  float schlick = f0 + (1.0 - f0) * s5;
  return clamp(schlick - b * (c * s5 * s), 0.0, 1.0);
}

// The selector, indices in the order of METHODS in methods.js (src/gl/methodIndex.js).
// v = (cos, nI or n, nT or k, f0 for conductors); e.x = b for F82. Unknown index: -1.
float fm_evaluate(int method, vec4 v, vec4 e) {
  if (method == 0) return fm_exact_cg(v.x, v.y, v.z);
  if (method == 1) return fm_exact_cg_literal(v.x, v.y, v.z);
  if (method == 2) return fm_exact_sp(v.x, v.y, v.z);
  if (method == 3) return fm_schlick_pow(v.x, v.y, v.z);
  if (method == 4) return fm_schlick_mul(v.x, v.y, v.z);
  if (method == 5) return fm_schlick_tir(v.x, v.y, v.z);
  if (method == 6) return fm_schlick_exp2(v.x, v.y, v.z);
  if (method == 7) return fm_conductor_exact(v.x, v.y, v.z, v.w, e.x);
  if (method == 8) return fm_conductor_schlick(v.x, v.y, v.z, v.w, e.x);
  if (method == 9) return fm_conductor_f82(v.x, v.y, v.z, v.w, e.x);
  return -1.0;
}
