// The hero view: three unit spheres side by side (exact Fresnel, Schlick, and the heatmap
// |exact − Schlick|), ray-cast analytically in one full-screen pass (trioCamera.js holds the same
// camera in JS). Exact normals and silhouettes with no mesh; the silhouette is anti-aliased by its
// coverage of the pixel, the background is the environment the spheres reflect. The sphere is a
// coated diffuse surface, k = mix(kd, ks, F) (lecture, "Fresnel reflection in lighting"): the
// lecture's heuristic, one F at the view angle; fresnel-lighting shows the layered coat beside it.
// The sky around the spheres depends on no optical constant: it is kept between frames, and a
// change of n redraws only the square round each sphere (createSphereTrio.js).
precision highp float;
#include <fresnel>
#include <environment>
#include <color>
#include <colormap>

uniform vec2 uResolution;  // drawing-buffer pixels
uniform float uSingle;     // -1: the three spheres side by side; 0, 1, 2: that one alone (a phone)
uniform vec3 uEye;         // camera position; the sphere is the unit sphere at the origin
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalfFov;
uniform float uNI;
uniform float uNT;
uniform vec3 uKd;          // linear RGB
uniform vec3 uKs;          // linear RGB
uniform float uEnvStrength;
uniform float uErrScale;   // the error that maps to the top of the legend
#ifdef BACKDROP
uniform sampler2D uBackdrop; // the sky, kept (createBackdrop.js)
#endif
out vec4 fragColor;

// Each view evaluates only what it shows (the mode is the same over a whole view, so the branch
// costs nothing on a GPU's SIMD lanes).
vec3 shade(int mode, vec3 N, vec3 V) {
  float cosTheta = clamp(dot(N, V), 0.0, 1.0);
  if (mode == 2) return colormap(abs(fresnelExact(cosTheta, uNI, uNT) - fresnelSchlick(cosTheta, uNI, uNT)) / uErrScale);
  float F = mode == 0 ? fresnelExact(cosTheta, uNI, uNT) : fresnelSchlick(cosTheta, uNI, uNT);
  vec3 L = normalize(uSunDir);
  vec3 R = reflect(-V, N);
  // Diffuse layer: the sun plus a little sky light from above; coating: the mirrored environment.
  vec3 diffuse = uKd * (max(dot(N, L), 0.0) + 0.3 * uEnvStrength * skyLight(N));
  vec3 coat = uKs * uEnvStrength * environment(R);
  return linearToSrgb(mix(diffuse, coat, F));
}

void main() {
  bool single = uSingle >= 0.0;
  float viewWidth = single ? uResolution.x : uResolution.x / 3.0;
  int slot = single ? 0 : int(min(2.0, floor(gl_FragCoord.x / viewWidth)));
  int mode = single ? int(uSingle) : slot;
  vec2 ndc = vec2((gl_FragCoord.x - float(slot) * viewWidth) / viewWidth, gl_FragCoord.y / uResolution.y) * 2.0 - 1.0;
  vec2 screen = ndc * uTanHalfFov * vec2(viewWidth / uResolution.y, 1.0);
  vec3 dir = normalize(uForward + screen.x * uRight + screen.y * uUp);
  // The ray passes the centre at distance d = √(|eye|² − b²); the silhouette is d = 1. Coverage
  // of the pixel by the disc: d's change across one pixel (fwidth) sets the width of the ramp.
  float b = dot(uEye, dir);
  float d = sqrt(max(dot(uEye, uEye) - b * b, 0.0));
  float coverage = clamp(0.5 + (1.0 - d) / max(fwidth(d), 1e-6), 0.0, 1.0);
#ifdef BACKDROP_PASS
  // The kept sky (createBackdrop.js): outside the squares round the spheres it is the picture.
  fragColor = vec4(linearToSrgb(environment(dir) * max(uEnvStrength, 0.15)), 1.0);
  return;
#endif
#ifdef BACKDROP
  // Drawn only in the square round each sphere: the sky beside the disc is the kept pixel itself.
  if (coverage <= 0.0) {
    fragColor = texelFetch(uBackdrop, ivec2(gl_FragCoord.xy), 0);
    return;
  }
#endif
  // The background (the environment the spheres reflect) only where the sphere does not cover the pixel.
  vec3 background = coverage < 1.0 ? linearToSrgb(environment(dir) * max(uEnvStrength, 0.15)) : vec3(0.0);
  if (coverage <= 0.0) {
    fragColor = vec4(background, 1.0);
    return;
  }
  // Nearer root of |eye + t·dir|² = 1; at the fringe just outside (h < 0) the grazing point.
  float h = b * b - (dot(uEye, uEye) - 1.0);
  float t = -b - sqrt(max(h, 0.0));
  vec3 N = normalize(uEye + t * dir);
  vec3 sphere = shade(mode, N, -dir);
  fragColor = vec4(mix(background, sphere, coverage), 1.0);
}
