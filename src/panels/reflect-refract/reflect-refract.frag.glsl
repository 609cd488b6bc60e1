// reflect-refract: a camera above a flat water (or glass) surface y = 0, ray-cast analytically.
// Each pixel's view ray meets the surface at its own angle θ from the normal; the exact Fresnel
// F(θ) splits it: colour = F·sky(reflected ray) + (1 − F)/n²·floor(refracted ray), in linear RGB.
// The 1/n² is the floor's radiance spreading into the wider cone above the water (physics.js).
// The floor is a checkered pool bottom at depth uDepth, reached by GLSL refract() (Snell).
// The sky a pixel shows or reflects depends on the view only: compiled with CACHE_PASS it is
// written to a float target, with CACHED read back (createShaderView's `cache`), so that moving n,
// the depth or the layer redraws F and the floor alone; with neither, one pass does it all.
precision highp float;
#include <fresnel>
#include <environment>
#include <color>

in vec2 vUv;
out vec4 fragColor;
uniform vec2 uResolution;
uniform float uElevation;   // view elevation above the surface, radians (90° looks straight down)
uniform float uDistance;    // camera to the point on the surface under the centre of the view
uniform float uTanHalfFov;  // tan(vertical field of view / 2)
uniform float uN;           // n_t of the water or glass; the camera is in air (n_i = 1)
uniform float uDepth;       // depth of the pool floor
uniform float uTile;        // tile size on the floor
uniform vec3 uTileA;        // floor colours, linear RGB
uniform vec3 uTileB;
uniform int uLayer;         // 0: both terms, 1: F·sky only, 2: (1 − F)/n²·floor only

// Checker whose tile (0, 0) is centred under the camera's centre ray at a steep view. Box-filtered
// over the pixel footprint (fwidth), so far tiles fade to their average instead of aliasing.
vec3 floorColour(vec2 p) {
  vec2 q = p / uTile + 0.5;
  vec2 w = max(fwidth(q), vec2(1e-4));
  // Integral of the square wave over [q − w/2, q + w/2], divided by w (filtered checker, after
  // Inigo Quilez, "Filtering the checkerboard pattern").
  vec2 i = 2.0 * (abs(fract((q - 0.5 * w) * 0.5) - 0.5) - abs(fract((q + 0.5 * w) * 0.5) - 0.5)) / w;
  float odd = 0.5 - 0.5 * i.x * i.y;
  return mix(uTileA, uTileB, odd);
}

// Value noise and a few fair-weather clouds on a flat deck above the camera, so the reflection is
// recognisable as the sky (clouds and all) and not mistaken for haze.
float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float valueNoise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), u.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0)), u.x), u.y);
}
vec3 sky(vec3 d) {
  vec3 base = skyLight(d);
  if (d.y <= 0.0) return base;
  vec2 p = d.xz / (d.y + 0.08) * 1.2;
  float n = (0.5 * valueNoise(p) + 0.25 * valueNoise(2.03 * p + 17.0) + 0.125 * valueNoise(4.01 * p + 3.0)) / 0.875;
  float cover = smoothstep(0.5, 0.72, n) * smoothstep(0.0, 0.12, d.y);
  return mix(base, vec3(1.0), 0.9 * cover);
}

vec3 viewDir() {
  vec2 ndc = vUv * 2.0 - 1.0;
  ndc.x *= uResolution.x / uResolution.y;
  float s = sin(uElevation);
  float c = cos(uElevation);
  vec3 forward = vec3(0.0, -s, -c);
  vec3 right = vec3(1.0, 0.0, 0.0);
  vec3 up = cross(right, forward);
  return normalize(forward + uTanHalfFov * (ndc.x * right + ndc.y * up));
}

vec3 eyePosition() {
  return uDistance * vec3(0.0, sin(uElevation), cos(uElevation));
}

// The sky seen along the ray, or mirrored by the surface below the horizon.
vec3 skyOf(vec3 d) {
  return d.y >= 0.0 ? sky(d) : sky(reflect(d, vec3(0.0, 1.0, 0.0)));
}

vec4 viewTerms() {
  return vec4(skyOf(viewDir()), 1.0);
}

#include <keptTerms>

#ifndef CACHE_PASS
void main() {
  vec3 d = viewDir();
  vec3 eye = eyePosition();
  vec3 skySeen = keptTerms().rgb;

  vec3 colour;
  if (d.y >= 0.0) {
    colour = uLayer == 2 ? vec3(0.0) : skySeen; // above the horizon: the sky itself
  } else {
    vec3 normal = vec3(0.0, 1.0, 0.0);
    vec3 hit = eye + (eye.y / -d.y) * d;
    float cosTheta = dot(-d, normal); // this pixel's angle between view ray and normal
    float F = fresnelExact(cosTheta, 1.0, uN);
    vec3 t = refract(d, normal, 1.0 / uN); // eta = n_i / n_t
    vec3 bottom = floorColour((hit + (uDepth / -t.y) * t).xz);
    vec3 reflected = F * skySeen;
    vec3 refracted = (1.0 - F) / (uN * uN) * bottom;
    colour = uLayer == 1 ? reflected : uLayer == 2 ? refracted : reflected + refracted;
  }
  fragColor = vec4(linearToSrgb(colour), 1.0);
}
#endif
