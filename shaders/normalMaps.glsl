// Analytic slope fields b = −∇h of the procedural maps, the GLSL twins of src/normals/
// createBumps.js, createGrooves.js, createSlopeChecker.js, createValueNoise.js and
// createMixedMap.js (same parameters; see those files for the geometry). The ground truth
// evaluates them at any sub-texel position. src/normals/mapUniforms.js fills every uniform below
// from a map object; left at 0, the new ones keep kinds 0–2 exactly as they were before.
// uMapKind: 0 bumps, 1 grooves, 2 checker, 3 noise, 4 mixed, 5 flat.
uniform int uMapKind;
uniform float uMapFreq;     // features per tile (mixed: blocks × per-block frequency)
uniform float uMapAngle;    // bumps: cap edge angle θm; grooves, checker, mixed: facet angle θ (radians)
uniform int uGrooveProfile; // 0 'v', 1 'sine'
uniform int uGrooveDirection; // 0 'u', 1 'v', 2 'diagonal'
uniform int uNoiseOctaves;  // 1..8
uniform float uNoiseGain;
uniform float uNoiseAmplitude;
uniform highp int uNoiseSeed; // the JS seed as int32 (Math.imul reads it mod 2^32 too)
uniform int uMixedBlocks;   // mixed: blocks per tile side
uniform float uMixedEdgeAngle; // mixed: the bumps' cap edge angle θm (radians)

const float FILL = 0.8; // createBumps' default cap diameter over cell side

vec2 bumpsSlope(vec2 uv, float freq, float edgeAngle) {
  float b = FILL * 0.5 / freq;
  float R = b / sin(edgeAngle);
  vec2 p = (fract(uv * freq) - 0.5) / freq;
  float r2 = dot(p, p);
  return r2 >= b * b ? vec2(0.0) : p / sqrt(R * R - r2);
}

// createGrooves' DIRECTIONS: the profile varies along u (0), v (1) or u + v (2).
vec2 groovesSlope(vec2 uv, float freq, float angle, int profile, int direction) {
  float t = fract(direction == 0 ? freq * uv.x : direction == 1 ? freq * uv.y : freq * uv.x + freq * uv.y);
  float tanT = tan(angle);
  float s = profile == 0 ? (t < 0.5 ? tanT : -tanT) : tanT * cos(6.28318531 * t);
  return direction == 0 ? vec2(s, 0.0) : direction == 1 ? vec2(0.0, s) : vec2(s * 0.70710678);
}

// createSlopeChecker with its default azimuth of 45°.
vec2 checkerSlope(vec2 uv, float freq, float angle) {
  vec2 cell = floor(uv * freq);
  float odd = mod(cell.x + cell.y, 2.0);
  float t = tan(angle) * 0.70710678;
  return odd > 0.5 ? vec2(-t) : vec2(t);
}

// createValueNoise's latticeValue, bit for bit: Math.imul is uint multiplication mod 2^32 and
// `>>>` is uint >>, so h is the same 32-bit integer; only the final float division rounds.
float latticeValue(highp uint i, highp uint j, highp uint seed) {
  highp uint h = (i * 0x27d4eb2du) ^ (j * 0x165667b1u) ^ (seed * 0x61c88647u);
  h = (h ^ (h >> 15)) * 0x2c1b3c6du;
  h = (h ^ (h >> 12)) * 0x297a2d39u;
  h ^= h >> 15;
  return float(h) / 4294967295.0 * 2.0 - 1.0;
}

float fade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
float fadeSlope(float t) { float s = t * (t - 1.0); return 30.0 * s * s; }

// fBm of value noise, octave o with lattice period P = freq·2^o wrapping mod P, slope
// −amplitude·gain^o·∇N_o (createValueNoise's derivation, after Quilez's "Value noise derivatives").
vec2 noiseSlope(vec2 uv, float freq) {
  vec2 g = vec2(0.0);
  float weight = uNoiseAmplitude;
  for (int o = 0; o < 8; o++) {
    if (o >= uNoiseOctaves) break;
    int P = int(freq) << o;
    vec2 x = fract(uv) * float(P);
    int i = min(P - 1, int(floor(x.x)));
    int j = min(P - 1, int(floor(x.y)));
    float tx = x.x - float(i);
    float ty = x.y - float(j);
    int i1 = i + 1 == P ? 0 : i + 1;
    int j1 = j + 1 == P ? 0 : j + 1;
    highp uint s = uint(uNoiseSeed) + uint(o) * 7919u;
    float a = latticeValue(uint(i), uint(j), s);
    float b = latticeValue(uint(i1), uint(j), s);
    float c = latticeValue(uint(i), uint(j1), s);
    float d = latticeValue(uint(i1), uint(j1), s);
    float k = a - b - c + d;
    g += weight * vec2(fadeSlope(tx) * (b - a + k * fade(ty)), fadeSlope(ty) * (c - a + k * fade(tx)));
    weight *= uNoiseGain;
  }
  return -g;
}

// createMixedMap: region (bi + 2·bj) mod 5 of flat, bumps, grooves, checker, noise; with
// f = uMapFreq (blocks × per-block frequency): bumps and noise at f, V-grooves at 2f (along u in
// even block rows, along v in odd ones), checker at 4f.
vec2 mixedSlope(vec2 uv) {
  ivec2 block = ivec2(floor(fract(uv) * float(uMixedBlocks))) % uMixedBlocks;
  int region = (block.x + 2 * block.y) % 5;
  float f = uMapFreq;
  if (region == 0) return vec2(0.0);
  if (region == 1) return bumpsSlope(uv, f, uMixedEdgeAngle);
  if (region == 2) return groovesSlope(uv, 2.0 * f, uMapAngle, 0, block.y % 2);
  if (region == 3) return checkerSlope(uv, 4.0 * f, uMapAngle);
  return noiseSlope(uv, f);
}

vec2 mapSlope(vec2 uv) {
  if (uMapKind == 0) return bumpsSlope(uv, uMapFreq, uMapAngle);
  if (uMapKind == 1) return groovesSlope(uv, uMapFreq, uMapAngle, uGrooveProfile, uGrooveDirection);
  if (uMapKind == 2) return checkerSlope(uv, uMapFreq, uMapAngle);
  if (uMapKind == 3) return noiseSlope(uv, uMapFreq);
  if (uMapKind == 4) return mixedSlope(uv);
  return vec2(0.0);
}
