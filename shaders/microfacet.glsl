// GGX microfacet specular in GLSL ES 3.00: the twin of src/optics/microfacet.js (same names, same
// order of operations; see the JS file for the sources: Walter et al. 2007, Heitz 2014).
const float MF_PI = 3.14159265358979;

// GGX normal distribution D(h) = α² / (π ((n·h)²(α² − 1) + 1)²), the base written
// (1 − c)(1 + c) + c²α² so that the peak keeps α² in float32 (see the JS twin).
float ggxDistribution(float cosThetaH, float alpha) {
  float c = clamp(cosThetaH, 0.0, 1.0);
  float a2 = alpha * alpha;
  float d = (1.0 - c) * (1.0 + c) + c * c * a2;
  return a2 / (MF_PI * d * d);
}

// Smith's Λ for GGX without tan: (√(c² + α²(1 − c²)) / c − 1) / 2; +Infinity at grazing (c = 0),
// as in the JS (the bit pattern of +Infinity: GLSL ES 3.00 has no infinity literal).
float smithLambda(float cosTheta, float alpha) {
  float c = clamp(cosTheta, 0.0, 1.0);
  float a2 = alpha * alpha;
  if (c == 0.0) return uintBitsToFloat(0x7f800000u);
  return 0.5 * (sqrt(c * c + a2 * ((1.0 - c) * (1.0 + c))) / c - 1.0);
}

// Height-correlated masking-shadowing G2 = 1 / (1 + Λ(l) + Λ(v)); 0 at or below the surface.
float smithG2(float cosL, float cosV, float alpha) {
  if (!(cosL > 0.0) || !(cosV > 0.0)) return 0.0;
  return 1.0 / (1.0 + smithLambda(cosL, alpha) + smithLambda(cosV, alpha));
}

// Cook–Torrance specular BRDF D·G2·F / (4 cosθl cosθv); 0 when either direction is at or below
// the surface (or not a number); the cosines clamped to 1 as the JS's checkCos does.
float microfacetSpecular(float cosL, float cosV, float cosH, float alpha, float F) {
  if (!(cosL > 0.0) || !(cosV > 0.0)) return 0.0;
  float D = ggxDistribution(cosH, alpha);
  float G = smithG2(cosL, cosV, alpha);
  return D * G * clamp(F, 0.0, 1.0) / (4.0 * min(cosL, 1.0) * min(cosV, 1.0));
}
