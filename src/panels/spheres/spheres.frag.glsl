// The hero view: a coated diffuse sphere, k = mix(kd, ks, F) (lecture, "Fresnel reflection in
// lighting"), with F exact (mode 0) or Schlick (mode 1), or the heatmap |exact − Schlick| (mode 2).
precision highp float;
#include <fresnel>
#include <environment>
#include <color>
#include <colormap>

uniform vec3 cameraPosition;
uniform int uMode;
uniform float uNI;
uniform float uNT;
uniform vec3 uKd;          // linear RGB
uniform vec3 uKs;          // linear RGB
uniform float uEnvStrength;
uniform float uErrScale;   // the error that maps to the top of the legend
in vec3 vWorldPos;
out vec4 fragColor;

void main() {
  // The sphere is centred at the origin: its exact normal is the normalized position, which
  // avoids the interpolation error of vertex normals (cos θ a little above 1 or off the true value).
  vec3 N = normalize(vWorldPos);
  vec3 V = normalize(cameraPosition - vWorldPos);
  float cosTheta = dot(N, V);
  float fExact = fresnelExact(cosTheta, uNI, uNT);
  float fSchlick = fresnelSchlick(cosTheta, uNI, uNT);
  if (uMode == 2) {
    fragColor = vec4(colormap(abs(fExact - fSchlick) / uErrScale), 1.0);
    return;
  }
  float F = uMode == 0 ? fExact : fSchlick;
  vec3 L = normalize(uSunDir);
  vec3 R = reflect(-V, N);
  // Diffuse layer: the sun plus a little sky light from above; coating: the mirrored environment.
  vec3 diffuse = uKd * (max(dot(N, L), 0.0) + 0.3 * uEnvStrength * skyLight(N));
  vec3 coat = uKs * uEnvStrength * environment(R);
  fragColor = vec4(linearToSrgb(mix(diffuse, coat, F)), 1.0);
}
