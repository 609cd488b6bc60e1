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

// The terms of a pixel that n does not touch: its linear colour when n plays no part (the
// background, the metal), with a = −1; on the dielectric, the environment it mirrors, with
// a = cos θ. Compiled with CACHE_PASS they go to a float target, with CACHED they are read back
// (createShaderView's `cache`), so that moving n draws the dielectric's F alone.
vec4 viewTerms() {
  StageHit hit = castStage();
  if (!hit.found) return vec4(environment(hit.dir), -1.0);
  float c = clamp(dot(hit.normal, hit.view), 0.0, 1.0);
  vec3 mirrored = environment(reflect(-hit.view, hit.normal));
  if (hit.side == 0) return vec4(mirrored, c);
  vec3 F = uMethod == 0
    ? fresnelConductorRGB(c, uMetalN, uMetalK)
    : vec3(schlickOn(c, uF0.r), schlickOn(c, uF0.g), schlickOn(c, uF0.b));
  return vec4(F * mirrored, -1.0);
}

#include <keptTerms>

#ifndef CACHE_PASS
void main() {
  vec4 terms = keptTerms();
  vec3 linear = terms.a < 0.0 ? terms.rgb : fresnelExact(terms.a, 1.0, uN) * terms.rgb;
  fragColor = vec4(linearToSrgb(linear), 1.0);
}
#endif
