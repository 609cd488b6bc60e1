// Asphalt under a low sun: a full-screen ray cast of a flat road (y = 0) and a procedural sky.
// Road: value-noise albedo (dark bitumen, lighter aggregate, wear) and micro-normals from a value-
// noise height field; GGX Cook–Torrance specular with F = fresnelExact on the half-vector angle
// (or the constant R0 when Fresnel is off) plus Lambert diffuse. Camera, sun and light levels come
// from physics.js beside it, which computes the panel's numbers for the same scene.
// Deliberately left out: sky reflected in the road (the lesson is the sun's highlight).
// The picture is radiance = A + uSun·K·F: A and K depend on the view, the sun and the roughness
// only, F on n and the Fresnel switch. Compiled three ways (createShaderView's `cache`):
// CACHE_PASS writes (A, K) into a float target; CACHED reads them back and adds F, so moving n or
// switching Fresnel costs one texel fetch and F per pixel; with neither, one pass does both.
precision highp float;
#include <fresnel>
#include <environment>
#include <color>
#include <microfacet>

uniform vec2 uResolution;
uniform vec3 uForward;
uniform vec3 uUp;
uniform vec3 uRight;
uniform float uTanHalfFov;
uniform float uCameraHeight;
uniform float uN;          // index of the road's binder (assumed; bitumen ~1.5–1.6)
uniform float uAlpha;      // GGX α = roughness²
uniform float uFresnel;    // 1: F exact at the half-vector angle; 0: F = R0 everywhere
uniform float uAlbedo;     // mean diffuse albedo
uniform vec3 uSun;         // sun irradiance (linear RGB)
uniform vec3 uAmbient;     // sky irradiance / π (linear RGB)
uniform float uExposure;
in vec2 vUv;
out vec4 fragColor;

// pcg2d integer hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020).
uvec2 pcg2d(uvec2 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  v = v ^ (v >> 16u);
  v.x += v.y * 1664525u;
  v.y += v.x * 1664525u;
  return v ^ (v >> 16u);
}

float hash(ivec2 c, uint seed) {
  return float(pcg2d(uvec2(c) + uvec2(seed, 0u)).x) * (1.0 / 4294967295.0);
}

// Value noise in [0, 1] with its analytic gradient, quintic interpolation
// (Quílez, "Value Noise Derivatives", 2008). Returns (value, d/dx, d/dz).
vec3 valueNoise(vec2 p, uint seed) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  vec2 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  ivec2 c = ivec2(i);
  float a = hash(c, seed);
  float b = hash(c + ivec2(1, 0), seed);
  float d = hash(c + ivec2(0, 1), seed);
  float e = hash(c + ivec2(1, 1), seed);
  float k1 = b - a;
  float k2 = d - a;
  float k3 = a - b - d + e;
  return vec3(a + k1 * u.x + k2 * u.y + k3 * u.x * u.y, du * vec2(k1 + k3 * u.y, k2 + k3 * u.x));
}

// 1 while a feature of this size spans several pixels, 0 once it is below one: detail that a pixel
// cannot show is replaced by its mean instead of aliasing into sparkle near the horizon.
float keep(float footprint, float size) {
  return 1.0 - smoothstep(0.25, 1.2, footprint / size);
}

// Aggregate: one stone per Worley cell (Worley, "A Cellular Texture Basis Function", SIGGRAPH 1996),
// a dome of radius R around a jittered centre. Returns (coverage, d height / dp (per cell unit), grey).
vec4 stones(vec2 p) {
  vec2 i = floor(p);
  vec2 f = p - i;
  float best = 1e9;
  vec2 toCentre = vec2(0.0);
  uvec2 id = uvec2(0u);
  for (int y = -1; y <= 1; y++) {
    for (int x = -1; x <= 1; x++) {
      uvec2 h = pcg2d(uvec2(ivec2(i) + ivec2(x, y)) + uvec2(71u, 5u));
      vec2 d = vec2(x, y) + 0.15 + 0.7 * vec2(h) * (1.0 / 4294967295.0) - f;
      float dd = dot(d, d);
      if (dd < best) { best = dd; toCentre = d; id = h; }
    }
  }
  float r = sqrt(best);
  float R = 0.36 + 0.2 * float(id.x >> 24u) / 255.0;
  float cover = 1.0 - smoothstep(0.85 * R, R, r);
  vec2 slope = r < R ? 2.0 * toCentre / (R * R) : vec2(0.0); // height 1 − r²/R²
  return vec4(cover, slope, float(id.y >> 24u) / 255.0);
}

// (A, K) of a road pixel: A the diffuse light, K the specular without F (times uSun·F later).
vec4 roadTerms(vec3 dir) {
  float t = min(uCameraHeight / -dir.y, 1e4);
  vec2 p = (t * dir).xz;
  // The pixel's footprint on the road: its ellipse has axes t·δ across the view and t·δ/|dir.y|
  // along it. Between the two (|dir.y|^0.7): the long axis alone blurs the near road at grazing,
  // the geometric mean lets the distance alias into stripes.
  float footprint = t * (2.0 * uTanHalfFov / uResolution.y) / pow(max(-dir.y, 1e-6), 0.7);

  // Three scales: wear and stains (2.5 m), aggregate stones (22 mm cells), grit (4 mm).
  float wear = valueNoise(p * 0.4, 11u).x;
  vec4 stone = stones(p * 45.0);
  vec3 grit = valueNoise(p * 260.0, 37u);
  float kStone = keep(footprint, 1.0 / 45.0);
  float kGrit = keep(footprint, 1.0 / 260.0);
  // Dark binder between lighter stones; the mix has a mean close to 1, which is what fades in.
  float near = mix(0.45, 1.35 * (0.7 + 0.6 * stone.w), stone.x) + 0.4 * (grit.x - 0.5) * kGrit;
  float variation = (1.0 + 0.3 * (wear - 0.5)) * mix(1.0, near, kStone);
  vec3 albedo = uAlbedo * variation * vec3(1.0, 0.98, 0.95);

  // Micro-normals: stones 2 mm high, grit 0.6 mm; slopes fade with the detail they come from.
  vec2 slope = 0.002 * 45.0 * stone.yz * kStone + 0.0006 * 260.0 * grit.yz * kGrit;
  vec3 N = normalize(vec3(-slope.x, 1.0, -slope.y));

  vec3 L = normalize(uSunDir);
  vec3 V = -dir;
  vec3 H = normalize(L + V);
  float cosL = dot(N, L);
  float spec = microfacetSpecular(cosL, dot(N, V), dot(N, H), uAlpha, 1.0);
  vec3 diffuse = albedo * (uSun * max(cosL, 0.0) / MF_PI + uAmbient);
  return vec4(diffuse, spec * max(cosL, 0.0));
}

// The sky of <environment> with a sun disc of 1° radius (the real one is 0.27°; larger to be seen).
vec3 sky(vec3 dir) {
  float c = dot(dir, normalize(uSunDir));
  return skyLight(dir) + vec3(40.0, 37.0, 33.0) * smoothstep(0.99985, 0.99995, c)
    + uSun * 0.15 * pow(max(c, 0.0), 400.0);
}

vec3 viewDir() {
  vec2 ndc = vUv * 2.0 - 1.0;
  float aspect = uResolution.x / uResolution.y;
  return normalize(uForward + ndc.x * uTanHalfFov * aspect * uRight + ndc.y * uTanHalfFov * uUp);
}

// (A, K) of this pixel; the sky has no specular term.
vec4 viewTerms() {
  vec3 dir = viewDir();
  return dir.y < 0.0 ? roadTerms(dir) : vec4(sky(dir), 0.0);
}

#include <keptTerms>

#ifndef CACHE_PASS
void main() {
  vec3 dir = viewDir();
  vec4 terms = keptTerms();
  // F on the half-vector angle: the microfacets that send the sun to the eye face along H.
  vec3 H = normalize(normalize(uSunDir) - dir);
  float F = uFresnel > 0.5 ? fresnelExact(dot(normalize(uSunDir), H), 1.0, uN) : normalIncidence(1.0, uN);
  vec3 radiance = terms.rgb + uSun * terms.a * clamp(F, 0.0, 1.0);
  // A smooth shoulder instead of a hard clip, so a brighter highlight always reads brighter.
  fragColor = vec4(linearToSrgb(1.0 - exp(-uExposure * radiance)), 1.0);
}
#endif
