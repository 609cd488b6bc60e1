// The background: the same procedural environment the spheres reflect.
precision highp float;
#include <environment>
#include <color>

uniform vec3 cameraPosition;
uniform float uEnvStrength;
in vec3 vWorldPos;
out vec4 fragColor;

void main() {
  vec3 sky = environment(vWorldPos - cameraPosition);
  fragColor = vec4(linearToSrgb(sky * max(uEnvStrength, 0.15)), 1.0);
}
