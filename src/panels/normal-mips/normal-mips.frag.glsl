// The receding plane of the normal-mips panel. One source, three passes (PASS, defined by the
// scene: one program per pass, since a software rasterizer pays for the code of every branch):
//   0 technique: the highlight from the chosen technique's uploaded mip chain → (linear RGB, LOD)
//   1 truth: uSamples jittered rays per pixel shaded with the exact analytic normals at base α,
//     folded into a running mean with the previous frames (uPrev) → (linear RGB, LOD)
//   2 display: split screen / difference / overlay of the two float targets, tone-mapped, sRGB.
// uDebug = 1 in pass 0 writes the decoded texel of level uForcedLevel at pixel-aligned texel
// centres (the test that every uploaded level is sampled exactly).
precision highp float;
precision highp int;
#include <fresnel>
#include <color>
#include <colormap>
#include <environment>
#include <lobeFormulas>
#include <normalMaps>

in vec2 vUv;
out vec4 fragColor;
uniform vec2 uResolution;
#ifndef PASS
#define PASS 0
#endif
uniform int uDebug;
// camera and light
uniform float uCamHeight;
uniform float uPitch;       // view direction below the horizon (radians)
uniform float uTanHalfFov;
uniform float uTile;        // world units per map tile
uniform float uLightPower;  // irradiance from the point light at the view centre
uniform vec3 uLightPos;     // world position of the point light
uniform float uLightDist2;  // its squared distance from the view centre (inverse-square reference)
uniform float uAniso;       // anisotropic filtering level in use (1: isotropic trilinear)
uniform float uIor;
uniform int uFresnel;       // 0 exact, 1 Schlick, 2 off (constant R0)
uniform float uKd;
// technique
uniform sampler2D uTexA;
uniform sampler2D uTexB;
uniform vec4 uScaleA;
uniform vec4 uOffsetA;
uniform vec4 uScaleB;
uniform vec4 uOffsetB;
uniform int uTechnique;     // 0 naive, 1 renormalized, 2 toksvig, 3 lean, 4 clean, 5 vmf
uniform int uChannels;
uniform float uAlpha;
uniform float uForcedLevel; // < 0: automatic
uniform float uMapSize;
uniform float uMaxLevel;
// truth
uniform sampler2D uPrev;
uniform int uSamples;
uniform int uFrame;
uniform float uBlend;
// display
uniform sampler2D uTech;
uniform sampler2D uTruth;
uniform int uView;          // 0 split, 1 technique, 2 truth, 3 difference
uniform int uOverlay;
uniform float uDiffScale;
// shimmer meter: a sub-pixel camera offset (pixels) for the technique pass
uniform vec2 uJitter;

// Camera at (0, h, 0) looking down by uPitch; pixel p in drawing-buffer pixels.
vec3 rayDir(vec2 p) {
  vec2 ndc = p / uResolution * 2.0 - 1.0;
  float aspect = uResolution.x / uResolution.y;
  vec3 f = vec3(0.0, -sin(uPitch), cos(uPitch));
  vec3 up = vec3(0.0, cos(uPitch), sin(uPitch));
  return normalize(f + ndc.x * uTanHalfFov * aspect * vec3(1.0, 0.0, 0.0) + ndc.y * uTanHalfFov * up);
}

// Tangent frame of the plane: T = +x, B = +z, N = +y (uv = xz / tile).
vec3 toTangent(vec3 w) { return vec3(w.x, w.z, w.y); }

// Radiance of a point with unit tangent-space normal n and NDF value d (implicit G: f = F·D/4),
// lit by the point light with irradiance E (normal to L) and the sky.
vec3 shade(vec3 n, float d, vec3 V, vec3 L, vec3 H, float E) {
  float nl = max(dot(n, L), 0.0);
  float vh = clamp(dot(V, H), 0.0, 1.0);
  float F = uFresnel == 0 ? fresnelExact(vh, 1.0, uIor)
    : uFresnel == 1 ? fresnelSchlick(vh, 1.0, uIor) : normalIncidence(1.0, uIor);
  vec3 nw = vec3(n.x, n.z, n.y);
  return E * nl * (uKd / 3.14159265 + F * d * 0.25) + uKd * 0.3 * skyLight(nw);
}

vec4 fetchA(vec2 uv) {
  vec4 raw = uForcedLevel < 0.0 ? texture(uTexA, uv) : textureLod(uTexA, uv, uForcedLevel);
  return uOffsetA + uScaleA * raw;
}
vec4 fetchB(vec2 uv) {
  vec4 raw = uForcedLevel < 0.0 ? texture(uTexB, uv) : textureLod(uTexB, uv, uForcedLevel);
  return uOffsetB + uScaleB * raw;
}

// The technique's lobe at uv (twin of texelLobe in effectiveRoughness.js) shaded for V, L.
vec3 techniqueRadiance(vec2 uv, vec3 V, vec3 L, float E) {
  vec3 H = normalize(V + L);
  vec4 a = fetchA(uv);
  if (uTechnique == 3 || uTechnique == 4) {
    vec2 b = a.xy;
    vec3 n = normalize(vec3(b, 1.0));
    if (uTechnique == 3) {
      vec3 cov = leanCovariance(b, vec3(a.z, a.w, fetchB(uv).x), uAlpha);
      return shade(n, leanD(H, b, cov), V, L, H, E);
    }
    float al = cleanAlpha(b, a.z, uAlpha);
    return shade(n, beckmannD(dot(n, H), al), V, L, H, E);
  }
  vec3 N = uChannels == 3 ? a.xyz : vec3(a.xy, reconstructZ(a.xy));
  float len = length(N);
  vec3 n = len > 0.0 ? N / len : vec3(0.0, 0.0, 1.0);
  float al = uAlpha;
  if (uTechnique == 2) al = toksvigAlpha(len, uAlpha);
  if (uTechnique == 5) al = vmfAlpha(uChannels == 3 ? a.w : a.z, uAlpha);
  return shade(n, beckmannD(dot(n, H), al), V, L, H, E);
}

// The mip level the hardware would pick: GL ES 3.0 §3.8.10 λ = log2 ρ, ρ the larger footprint
// axis in texels; with anisotropic filtering (EXT_texture_filter_anisotropic) N = min(⌈ρmax/ρmin⌉,
// level) taps along the long axis and λ = log2(ρmax/N). Real GPUs approximate both a little.
float lodAt(vec2 uv) {
  float px = length(dFdx(uv) * uMapSize);
  float py = length(dFdy(uv) * uMapSize);
  float pmax = max(max(px, py), 1e-6);
  float n = min(ceil(pmax / max(min(px, py), 1e-6)), uAniso);
  return uForcedLevel >= 0.0 ? uForcedLevel : clamp(log2(pmax / n), 0.0, uMaxLevel);
}

// The point light at a world point: direction (tangent space) and irradiance, inverse-square,
// equal to uLightPower at the view centre.
vec4 lightAt(vec3 hit) {
  vec3 toLight = uLightPos - hit;
  float d2 = dot(toLight, toLight);
  return vec4(toTangent(toLight / sqrt(d2)), uLightPower * uLightDist2 / d2);
}

uint hash(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}
float rand(inout uint state) {
  state = hash(state);
  return float(state >> 8) / 16777216.0;
}

vec3 truthRadiance(vec2 pixel) {
  uint state = hash(uint(pixel.x) * 1973u + uint(pixel.y) * 9277u + uint(uFrame) * 26699u);
  vec3 sum = vec3(0.0);
  for (int s = 0; s < 64; s++) {
    if (s >= uSamples) break;
    vec2 p = floor(pixel) + vec2(rand(state), rand(state));
    vec3 dir = rayDir(p);
    if (dir.y >= -1e-5) { sum += environment(dir); continue; }
    vec3 hit = vec3(0.0, uCamHeight, 0.0) + dir * (uCamHeight / -dir.y);
    vec3 V = toTangent(-dir);
    vec4 light = lightAt(hit);
    vec3 H = normalize(V + light.xyz);
    vec2 b = mapSlope(fract(hit.xz / uTile));
    vec3 n = normalize(vec3(b, 1.0));
    sum += shade(n, beckmannD(dot(n, H), uAlpha), V, light.xyz, H, light.w);
  }
  return sum / float(uSamples);
}

vec3 toneMap(vec3 x) { return 1.0 - exp(-max(x, 0.0)); } // twin of toneMap in src/optics/bandedRmse.js

vec3 levelColour(float lod) {
  return colormap(clamp(lod / max(uMaxLevel, 1.0), 0.0, 1.0));
}

void main() {
  vec2 pixel = gl_FragCoord.xy;
  if (PASS == 2) {
    ivec2 ip = ivec2(pixel);
    vec4 tech = texelFetch(uTech, ip, 0);
    vec4 truth = texelFetch(uTruth, ip, 0);
    bool left = pixel.x < 0.5 * uResolution.x;
    vec4 shown = uView == 1 || (uView == 0 && left) ? tech : truth;
    vec3 c = toneMap(shown.rgb);
    if (uView == 3) {
      float e = length(toneMap(tech.rgb) - toneMap(truth.rgb)) / 1.7320508;
      c = tech.a < 0.0 ? vec3(0.0) : srgbToLinear(colormap(clamp(e / uDiffScale, 0.0, 1.0)));
    }
    if (uOverlay == 1 && shown.a >= 0.0) c = mix(c, srgbToLinear(levelColour(shown.a)), 0.45);
    if (uView == 0 && abs(pixel.x - 0.5 * uResolution.x) < 1.5) c = vec3(1.0);
    fragColor = vec4(linearToSrgb(c), 1.0);
    return;
  }
  if (PASS == 0 && uDebug > 0) {
    float levelSize = max(1.0, floor(uMapSize / exp2(uForcedLevel)));
    vec2 uv = (mod(floor(pixel), levelSize) + 0.5) / levelSize;
    fragColor = uDebug == 2 ? fetchB(uv) : fetchA(uv);
    return;
  }
  // uv and its derivatives in uniform control flow (sky pixels get a far, unused point).
  vec3 dir = rayDir(pixel + (PASS == 0 ? uJitter : vec2(0.0)));
  bool sky = dir.y >= -1e-5;
  vec3 hit = vec3(0.0, uCamHeight, 0.0) + dir * min(uCamHeight / max(-dir.y, 1e-5), 1e4);
  vec2 uv = hit.xz / uTile;
  float lod = lodAt(uv);
  if (PASS == 0) {
    vec4 light = lightAt(hit);
    vec3 rad = techniqueRadiance(uv, toTangent(-dir), light.xyz, light.w);
    fragColor = sky ? vec4(environment(dir), -1.0) : vec4(rad, lod);
    return;
  }
  vec3 prev = texelFetch(uPrev, ivec2(pixel), 0).rgb;
  fragColor = vec4(mix(prev, truthRadiance(pixel), uBlend), sky ? -1.0 : lod);
}
