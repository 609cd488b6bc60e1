// Per-texel lobes of each mip technique: the GLSL twin of src/normals/lobeFormulas.js and of
// texelLobe() in src/normals/effectiveRoughness.js (same names, same clamps). α is the
// Beckmann roughness; sources are in the JS files.

// Toksvig's σ² = (1 − L)/L from L = |N_a| (JS: toksvigVariance); L ≥ 1 gives 0.
float toksvigVariance(float L) {
  if (L >= 1.0) return 0.0;
  return L > 0.0 ? (1.0 - L) / L : 1e30;
}

// α'² = (α² + 2σ²(1 − α²)) / (1 + 2σ²(1 − α²)) (JS: toksvigAlpha).
float toksvigAlpha(float L, float alpha) {
  float v = toksvigVariance(L);
  if (v >= 1e30) return 1.0;
  float a2 = alpha * alpha;
  float k = 2.0 * v * (1.0 - a2);
  return sqrt((a2 + k) / (1.0 + k));
}

// κ ≈ (3r − r³)/(1 − r²), 10000 for r ≥ 1 (JS: vmfKappa).
float vmfKappa(float r) {
  if (r >= 1.0) return 10000.0;
  if (!(r > 0.0)) return 0.0;
  return (3.0 * r - r * r * r) / (1.0 - r * r);
}

// α' = √(α² + 2/κ) (JS: vmfAlpha); κ = 0 has no lobe at all: α' = 1 here (fully rough).
float vmfAlpha(float r, float alpha) {
  float kappa = vmfKappa(r);
  return kappa == 0.0 ? 1.0 : sqrt(alpha * alpha + 2.0 / kappa);
}

// CLEAN: σ² = max(0, M − |B|²), α' = √(α² + σ²) (JS: cleanVariance, cleanAlpha).
float cleanAlpha(vec2 b, float m, float alpha) {
  return sqrt(alpha * alpha + max(0.0, m - dot(b, b)));
}

// LEAN: Σ = M − B Bᵀ + (α²/2) I, variances clamped at 0 and |Σxy| at √(ΣxxΣyy)
// (JS: leanCovariance). Returns (Σxx, Σyy, Σxy).
vec3 leanCovariance(vec2 b, vec3 m, float alpha) {
  float v0 = 0.5 * alpha * alpha;
  float cxx = max(0.0, m.x - b.x * b.x);
  float cyy = max(0.0, m.y - b.y * b.y);
  float lim = sqrt(cxx * cyy);
  float cxy = clamp(m.z - b.x * b.y, -lim, lim);
  return vec3(cxx + v0, cyy + v0, cxy);
}

// z of a 2-channel normal (JS: reconstructZ).
float reconstructZ(vec2 xy) {
  return sqrt(max(0.0, 1.0 - dot(xy, xy)));
}

// Beckmann NDF about the shading normal, cosH = n·h: exp(−tan²θ/α²)/(π α² cos⁴θ)
// (Walter et al., "Microfacet Models for Refraction", EGSR 2007, eq. 25). Its slope-space form is
// the Gaussian of variance α²/2 per axis, LEAN's base lobe, so both families match at level 0.
float beckmannD(float cosH, float alpha) {
  if (cosH <= 0.0) return 0.0;
  float c2 = cosH * cosH;
  float a2 = alpha * alpha;
  return exp((c2 - 1.0) / (c2 * a2)) / (3.14159265 * a2 * c2 * c2);
}

// LEAN's NDF: a slope-space Gaussian about the mean slope B with covariance Σ, over cos⁴θh
// (Olano & Baker 2010 with the errata's 1/(2π√|Σ|)); hT is the half vector in tangent space.
float leanD(vec3 hT, vec2 b, vec3 cov) {
  if (hT.z <= 0.0) return 0.0;
  vec2 h = hT.xy / hT.z - b;
  float det = max(cov.x * cov.y - cov.z * cov.z, 1e-12);
  float e = (h.x * h.x * cov.y + h.y * h.y * cov.x - 2.0 * h.x * h.y * cov.z) / det;
  float c2 = hT.z * hT.z;
  return exp(-0.5 * e) / (6.28318531 * sqrt(det) * c2 * c2);
}
