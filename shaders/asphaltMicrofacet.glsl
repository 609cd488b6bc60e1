// GGX microfacet specular in GLSL ES 3.00: the twin of src/optics/microfacet.js (same names, same
// order of operations; see the JS file for the sources: Walter et al. 2007, Heitz 2014).
const float MF_PI = 3.14159265358979;

// GGX normal distribution D(h) = α² / (π ((n·h)²(α² − 1) + 1)²).
float ggxDistribution(float cosThetaH, float alpha) {
  float c = clamp(cosThetaH, 0.0, 1.0);
  float a2 = alpha * alpha;
  float d = c * c * (a2 - 1.0) + 1.0;
  return a2 / (MF_PI * d * d);
}

// Smith's Λ for GGX without tan: (√(c² + α²(1 − c²)) / c − 1) / 2; large at grazing.
float smithLambda(float cosTheta, float alpha) {
  float c = max(clamp(cosTheta, 0.0, 1.0), 1e-6);
  float a2 = alpha * alpha;
  return 0.5 * (sqrt(c * c + a2 * ((1.0 - c) * (1.0 + c))) / c - 1.0);
}

// Height-correlated masking-shadowing G2 = 1 / (1 + Λ(l) + Λ(v)).
float smithG2(float cosL, float cosV, float alpha) {
  return 1.0 / (1.0 + smithLambda(cosL, alpha) + smithLambda(cosV, alpha));
}

// Cook–Torrance specular BRDF D·G2·F / (4 cosθl cosθv); 0 when either direction is below the surface.
float microfacetSpecular(float cosL, float cosV, float cosH, float alpha, float F) {
  if (cosL <= 0.0 || cosV <= 0.0) return 0.0;
  float D = ggxDistribution(cosH, alpha);
  float G = smithG2(cosL, cosV, alpha);
  return D * G * clamp(F, 0.0, 1.0) / (4.0 * cosL * cosV);
}
