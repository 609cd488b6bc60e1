// Fresnel reflectance in GLSL ES 3.00: the twin of src/optics/fresnel.js.
// Same names and clamps, and the same order of operations except where the JS uses exact float64
// helpers: g² (cosTransmittedSq below) and, in the conductor, 1 − c (twoSum) and √(t0² + 4n²k²)
// (Math.hypot). See the JS file for sources.
// Values that JS returns as null (no transmitted ray, no critical angle) are -1.0 here.
// Precision: the including shader declares `precision highp float;` (or mediump to study fp16).

// cos²θt = g² = (1 − m)(1 + m) + c² with m = nI/nT and c = m·cosθi, evaluated as
// ((nT − nI)/nT)·((nT + nI)/nT) + c·c. The JS computes the same quantity as
// (nT² − nI² + (nI·cosθi)²)/nT² from exact products summed in double-double, which float32 has no
// cheap way to do. Where it matters the two agree: neither forms 1 + c², and the index term is
// exactly 0 for matched indices (nT − nI is exact for nearby indices), so c² survives at grazing.
// They differ in rounding: here each operation rounds to float32, and the final sum cancels as
// g² → 0 near the critical angle, so g² loses relative precision there. That is harmless: R is
// ill-conditioned there anyway, and tests/e2e/gpuTwin.spec.js compares by angle within 0.02 rad
// of θc (the GPU value must be the JS value at some angle within 1e-5 rad, ± 2e-6); everywhere
// else it requires |GPU − JS| ≤ 2e-6.
float cosTransmittedSq(float ci, float nI, float nT) {
  float c = nI * ci / nT;
  return ((nT - nI) / nT) * ((nT + nI) / nT) + c * c;
}

// Snell's law: cos θt, or -1.0 under total internal reflection.
float snellCosT(float cosThetaI, float nI, float nT) {
  float g2 = cosTransmittedSq(clamp(cosThetaI, 0.0, 1.0), nI, nT);
  return g2 < 0.0 ? -1.0 : sqrt(g2);
}

// Exact unpolarized reflectance, the lecture's c/g form with the safe ordering of g², before any
// clamp (ci must be in [0, 1] for a physical result). Shared with fresnelMethods.glsl.
float fresnelExactRaw(float ci, float nI, float nT) {
  if (nI == nT) return 0.0;
  float g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0.0) return 1.0;
  float g = sqrt(g2);
  float c = nI * ci / nT;
  float a = (g - c) / (g + c);
  // (c(g+c) − m²)/(c(g−c) + m²) with c² − m² = −m²sin²θi substituted (no cancellation).
  float m = nI / nT;
  float ms2 = m * m * ((1.0 - ci) * (1.0 + ci));
  float cg = c * g;
  float b = (cg - ms2) / (cg + ms2);
  return 0.5 * a * a * (1.0 + b * b);
}


// Exact unpolarized reflectance with the contract's clamps.
float fresnelExact(float cosThetaI, float nI, float nT) {
  return clamp(fresnelExactRaw(clamp(cosThetaI, 0.0, 1.0), nI, nT), 0.0, 1.0);
}

// (Rs, Rp) from the s/p Fresnel equations.
vec2 fresnelPolarized(float cosThetaI, float nI, float nT) {
  float ci = clamp(cosThetaI, 0.0, 1.0);
  if (nI == nT) return vec2(0.0);
  float g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0.0) return vec2(1.0);
  float ct = sqrt(g2);
  float rs = (nI * ci - nT * ct) / (nI * ci + nT * ct);
  float rp = (nT * ci - nI * ct) / (nT * ci + nI * ct);
  return clamp(vec2(rs * rs, rp * rp), 0.0, 1.0);
}

// (Ts, Tp) power transmittances; Rs + Ts = 1 and Rp + Tp = 1.
vec2 fresnelTransmittance(float cosThetaI, float nI, float nT) {
  float ci = clamp(cosThetaI, 0.0, 1.0);
  if (nI == nT) return vec2(1.0);
  float g2 = cosTransmittedSq(ci, nI, nT);
  if (g2 <= 0.0) return vec2(0.0);
  float ct = sqrt(g2);
  float num = 4.0 * nI * ci * nT * ct;
  float ds = nI * ci + nT * ct;
  float dp = nT * ci + nI * ct;
  return clamp(vec2(num / (ds * ds), num / (dp * dp)), 0.0, 1.0);
}

// R0 = ((nT − nI)/(nT + nI))².
float normalIncidence(float nI, float nT) {
  float r = (nT - nI) / (nT + nI);
  return r * r;
}

float schlickOn(float c, float r0) {
  float x = 1.0 - c;
  float x2 = x * x;
  return clamp(r0 + (1.0 - r0) * (x2 * x2 * x), 0.0, 1.0);
}

// Schlick on cos θi, as on the slide (no total internal reflection).
float fresnelSchlick(float cosThetaI, float nI, float nT) {
  return schlickOn(clamp(cosThetaI, 0.0, 1.0), normalIncidence(nI, nT));
}

// Schlick on cos θt when nI > nT; 1 past the critical angle.
float fresnelSchlickTIR(float cosThetaI, float nI, float nT) {
  float ci = clamp(cosThetaI, 0.0, 1.0);
  float r0 = normalIncidence(nI, nT);
  if (nI <= nT) return schlickOn(ci, r0);
  float g2 = cosTransmittedSq(ci, nI, nT);
  return g2 <= 0.0 ? 1.0 : schlickOn(sqrt(g2), r0);
}

// three.js F_Schlick: the spherical-Gaussian exp2 form.
float fresnelSchlickExp2(float cosThetaI, float nI, float nT) {
  float c = clamp(cosThetaI, 0.0, 1.0);
  float r0 = normalIncidence(nI, nT);
  return clamp(r0 + (1.0 - r0) * exp2((-5.55473 * c - 6.98316) * c), 0.0, 1.0);
}

// Critical angle in radians, or -1.0 when nI <= nT.
float criticalAngle(float nI, float nT) {
  return nI > nT ? asin(nT / nI) : -1.0;
}

// Brewster angle in radians.
float brewsterAngle(float nI, float nT) {
  return atan(nT, nI);
}

// (Rs, Rp) from air into a conductor n + ik before any clamp (Lagarde 2013; stable a², b² as in
// the JS). Shared with the unclamped method twin in fresnelMethods.glsl.
vec2 conductorPolarizedRaw(float c, float n, float k) {
  float sin2 = (1.0 - c) * (1.0 + c);
  float t0 = n * n - k * k - sin2;
  float nk = n * k;
  float S = sqrt(t0 * t0 + 4.0 * nk * nk);
  float a2;
  float b2;
  if (t0 >= 0.0) {
    a2 = 0.5 * (S + t0);
    b2 = a2 > 0.0 ? nk * nk / a2 : 0.0;
  } else {
    b2 = 0.5 * (S - t0);
    a2 = nk * nk / b2;
  }
  float a = sqrt(a2);
  float dm = a - c;
  float dp = a + c;
  float rsDen = dp * dp + b2;
  if (rsDen <= 0.0) return vec2(0.0);
  float rs = (dm * dm + b2) / rsDen;
  if (rs <= 0.0) return vec2(0.0);
  float um = a * c - sin2;
  float up = a * c + sin2;
  float bc = sqrt(b2) * c;
  float rpDen = up * up + bc * bc;
  float rp = rpDen > 0.0 ? rs * ((um * um + bc * bc) / rpDen) : rs;
  return vec2(rs, rp);
}


// (Rs, Rp) from air into a conductor n + ik.
vec2 fresnelConductorPolarized(float cosThetaI, float n, float k) {
  return clamp(conductorPolarizedRaw(clamp(cosThetaI, 0.0, 1.0), n, k), 0.0, 1.0);
}

float fresnelConductor(float cosThetaI, float n, float k) {
  vec2 sp = fresnelConductorPolarized(cosThetaI, n, k);
  return clamp(0.5 * (sp.x + sp.y), 0.0, 1.0);
}

// Per-channel conductor reflectance for RGB (n, k at 650/550/450 nm).
vec3 fresnelConductorRGB(float cosThetaI, vec3 n, vec3 k) {
  return vec3(
    fresnelConductor(cosThetaI, n.r, k.r),
    fresnelConductor(cosThetaI, n.g, k.g),
    fresnelConductor(cosThetaI, n.b, k.b));
}
