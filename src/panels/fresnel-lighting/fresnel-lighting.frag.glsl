// fresnel-lighting: a diffuse sphere under a shiny coat, k = mix(kd, ks, F) (lecture, "Fresnel
// reflection in lighting"), or the layered coat the lecture's heuristic stands for, on the first
// sphere; the same sphere with a constant weight w on the second.
// F is taken at the view angle N·V: the coat is a mirror, and the half vector between V and the
// mirrored ray reflect(−V, N) is N itself, so the lecture's V·H is N·V here.
precision highp float;
#include <fresnel>
#include <environment>
#include <color>
#include <twinStage>

uniform vec3 uKd;       // linear RGB
uniform vec3 uKs;       // linear RGB
uniform float uN;       // the coat's refractive index (seen from air)
uniform float uWeight;  // the constant weight w of the second sphere, the one without F
uniform int uMethod;    // F on the first sphere: 0 exact, 1 Schlick, 2 the layered coat
uniform float uRi;      // diffuse light the coat's underside reflects back (diffuseFresnel.js)
uniform float uRe;      // diffuse sky light the coat reflects from above
out vec4 fragColor;

void main() {
  StageHit hit = castStage();
  if (!hit.found) {
    fragColor = vec4(linearToSrgb(environment(hit.dir)), 1.0);
    return;
  }
  vec3 N = hit.normal;
  vec3 V = hit.view;
  // What each layer sends to the eye: the diffuse layer lit by the sun and a little sky light
  // (as in the hero), the coat mirroring the environment (sun disc included).
  vec3 albedo = uKd;
  float cosL = max(dot(N, normalize(uSunDir)), 0.0);
  float sun = cosL;
  vec3 sky = 0.3 * skyLight(N);
  vec3 kd = albedo * (sun + sky);
  vec3 ks = uKs * environment(reflect(-V, N));
  float n = uN;
  float w = uWeight;
  float ri = uRi;
  float re = uRe;
  // The panel shows this included file, character for character, under the picture.
  #include <fresnel-lighting-mix>
  vec3 k = hit.side == 1 ? kConstant : (uMethod == 0 ? kExact : uMethod == 1 ? kSchlick : kLayered);
  fragColor = vec4(linearToSrgb(k), 1.0);
}
