// Changing specular: one flat tiled floor rendered twice, side by side. Left: Phong's highlight
// k_s·(v·r)^s with k_s = R0; right: the same lobe times F(θ), θ between the normal and the light
// (lecture, "Changing Specular" and "Reflection Math"). The light is directional, so F is the same
// all over the floor: the right half is the left half scaled by F/R0, nothing else.
// The JS twin of the numbers is src/optics/phong.js.
// Only k depends on n: the other terms of a pixel (its diffuse light or sky, and its lobe) are
// compiled with CACHE_PASS into a float target and with CACHED read back (createShaderView's
// `cache`), so that moving n draws k alone.
precision highp float;
#include <fresnel>
#include <environment>
#include <color>

uniform vec2 uResolution;
uniform float uStacked; // 1: Phong above Phong × F (a phone); 0: side by side
uniform float uViewEl;     // radians above the floor; the camera looks at the origin
uniform float uTanHalfFov;
uniform float uCameraDist;
uniform float uS;          // Phong exponent
uniform float uN;          // index of the floor (from air, n_i = 1)
uniform float uLight;      // light strength for the highlight and the diffuse floor
uniform float uExposure;
in vec2 vUv;
out vec4 fragColor;

// A dark glossy floor of 0.5 m tiles with lighter grout lines, antialiased with fwidth.
vec3 floorAlbedo(vec2 p) {
  vec2 cell = floor(p * 2.0);
  float checker = mod(cell.x + cell.y, 2.0);
  vec2 g = abs(fract(p * 2.0) - 0.5);
  vec2 w = fwidth(p * 2.0);
  float grout = 1.0 - min(smoothstep(0.485 - w.x, 0.485 + w.x, g.x) + smoothstep(0.485 - w.y, 0.485 + w.y, g.y), 1.0);
  vec3 tile = mix(vec3(0.030, 0.036, 0.050), vec3(0.050, 0.056, 0.070), checker);
  return mix(vec3(0.12), tile, grout);
}

// (rgb: what does not scale with k, the diffuse floor or the sky; a: the lobe) of a ray.
vec4 termsOf(vec3 dir, vec3 camPos) {
  vec3 L = normalize(uSunDir);
  if (dir.y >= 0.0) {
    float sun = smoothstep(0.9997, 0.9999, dot(dir, L));
    return vec4(skyLight(dir) * 0.6 + sun * vec3(30.0), 0.0);
  }
  vec3 p = camPos + dir * (-camPos.y / dir.y);
  vec3 N = vec3(0.0, 1.0, 0.0);
  vec3 R = reflect(-L, N);
  float lobe = pow(max(dot(-dir, R), 0.0), uS);
  float cosTheta = max(dot(N, L), 0.0);
  vec3 diffuse = floorAlbedo(p.xz) * (uLight * cosTheta / 3.14159265 + 0.4 * skyLight(N));
  return vec4(diffuse, lobe);
}

// Whether this pixel is in the Phong × F view: the right half, or stacked the lower half.
bool inFresnelView() {
  return uStacked > 0.5 ? vUv.y < 0.5 : vUv.x >= 0.5;
}

// The view ray of this pixel, in the left (top) or the right (bottom) view.
vec3 viewDir(out vec3 camPos) {
  bool stacked = uStacked > 0.5;
  vec2 ndc = stacked ? vec2(vUv.x * 2.0 - 1.0, fract(vUv.y * 2.0) * 2.0 - 1.0)
                     : vec2(fract(vUv.x * 2.0) * 2.0 - 1.0, vUv.y * 2.0 - 1.0);
  float aspect = stacked ? uResolution.x / (0.5 * uResolution.y) : 0.5 * uResolution.x / uResolution.y;
  vec3 forward = vec3(0.0, -sin(uViewEl), cos(uViewEl));
  vec3 up = vec3(0.0, cos(uViewEl), sin(uViewEl));
  vec3 side = vec3(-1.0, 0.0, 0.0);
  camPos = -forward * uCameraDist;
  return normalize(forward + ndc.x * uTanHalfFov * aspect * side + ndc.y * uTanHalfFov * up);
}

vec4 viewTerms() {
  vec3 camPos;
  vec3 dir = viewDir(camPos);
  return termsOf(dir, camPos);
}

#include <keptTerms>

#ifndef CACHE_PASS
void main() {
  vec4 terms = keptTerms();
  // The light is directional: θ, and so k, is the same at every point of a view.
  float cosTheta = max(normalize(uSunDir).y, 0.0);
  float k = inFresnelView() ? fresnelExact(cosTheta, 1.0, uN) : normalIncidence(1.0, uN);
  vec3 color = terms.rgb + vec3(uLight * k * terms.a);
  // A dividing line two pixels wide between the halves.
  float divide = uStacked > 0.5 ? step(abs(gl_FragCoord.y - 0.5 * uResolution.y), 1.0)
                                : step(abs(gl_FragCoord.x - 0.5 * uResolution.x), 1.0);
  vec3 display = 1.0 - exp(-uExposure * color);
  fragColor = vec4(mix(linearToSrgb(display), vec3(0.0), divide), 1.0);
}
#endif
