// metals: a dielectric (left) and a conductor (right), each showing only its mirror reflection of
// the environment, weighted by its Fresnel reflectance: F·environment(R). The dielectric's F is
// grey; the metal's is per RGB channel from its complex index n + ik at 650/550/450 nm, exact
// (fresnelConductorRGB) or Schlick with the channel's own F0.
precision highp float;
#include <fresnel>
#include <environment>
#include <color>
#include <twinStage>

uniform float uN;       // the dielectric's index, seen from air
uniform vec3 uMetalN;   // metal: n per channel (R, G, B)
uniform vec3 uMetalK;   // metal: k per channel
uniform vec3 uF0;       // metal: F0 per channel, from the float64 reference
uniform int uMethod;    // metal: 0 exact, 1 Schlick
out vec4 fragColor;

void main() {
  StageHit hit = castStage();
  if (!hit.found) {
    fragColor = vec4(linearToSrgb(environment(hit.dir)), 1.0);
    return;
  }
  float c = clamp(dot(hit.normal, hit.view), 0.0, 1.0);
  vec3 F;
  if (hit.side == 0) {
    F = vec3(fresnelExact(c, 1.0, uN));
  } else if (uMethod == 0) {
    F = fresnelConductorRGB(c, uMetalN, uMetalK);
  } else {
    F = vec3(schlickOn(c, uF0.r), schlickOn(c, uF0.g), schlickOn(c, uF0.b));
  }
  fragColor = vec4(linearToSrgb(F * environment(reflect(-hit.view, hit.normal))), 1.0);
}
