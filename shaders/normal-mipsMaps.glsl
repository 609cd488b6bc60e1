// Analytic slope fields b = −∇h of the procedural maps, the GLSL twins of
// src/normals/createBumps.js, createGrooves.js and createSlopeChecker.js (same parameters; see
// those files for the geometry). The ground truth evaluates them at any sub-texel position.
// uMapKind: 0 bumps, 1 grooves, 2 checker.
uniform int uMapKind;
uniform float uMapFreq;
uniform float uMapAngle;    // bumps: cap edge angle θm; grooves, checker: facet angle θ (radians)
uniform int uGrooveProfile; // 0 'v', 1 'sine'

const float FILL = 0.8; // createBumps' default cap diameter over cell side

vec2 bumpsSlope(vec2 uv) {
  float b = FILL * 0.5 / uMapFreq;
  float R = b / sin(uMapAngle);
  vec2 p = (fract(uv * uMapFreq) - 0.5) / uMapFreq;
  float r2 = dot(p, p);
  return r2 >= b * b ? vec2(0.0) : p / sqrt(R * R - r2);
}

// Direction 'u': the profile varies along u (createGrooves' default).
vec2 groovesSlope(vec2 uv) {
  float t = fract(uMapFreq * uv.x);
  float tanT = tan(uMapAngle);
  float s = uGrooveProfile == 0 ? (t < 0.5 ? tanT : -tanT) : tanT * cos(6.28318531 * t);
  return vec2(s, 0.0);
}

// createSlopeChecker with its default azimuth of 45°.
vec2 checkerSlope(vec2 uv) {
  vec2 cell = floor(uv * uMapFreq);
  float odd = mod(cell.x + cell.y, 2.0);
  float t = tan(uMapAngle) * 0.70710678;
  return odd > 0.5 ? vec2(-t) : vec2(t);
}

vec2 mapSlope(vec2 uv) {
  if (uMapKind == 0) return bumpsSlope(uv);
  if (uMapKind == 1) return groovesSlope(uv);
  return checkerSlope(uv);
}
