// A procedural environment, so no image is downloaded: a sky gradient, a darker ground with a
// soft horizon, and a sun disc in the light's direction. Linear RGB; direction need not be unit.
uniform vec3 uSunDir;

// Sky and ground without the sun: the soft light a diffuse surface sees.
vec3 skyLight(vec3 dir) {
  vec3 d = normalize(dir);
  float y = d.y;
  vec3 zenith = vec3(0.10, 0.28, 0.70);
  vec3 horizon = vec3(0.75, 0.82, 0.90);
  vec3 ground = vec3(0.16, 0.13, 0.10);
  vec3 sky = mix(horizon, zenith, pow(clamp(y, 0.0, 1.0), 0.5));
  vec3 below = mix(horizon * 0.5, ground, clamp(-y * 4.0, 0.0, 1.0));
  return y >= 0.0 ? sky : below;
}

vec3 environment(vec3 dir) {
  vec3 d = normalize(dir);
  float sun = smoothstep(0.9955, 0.9975, dot(d, normalize(uSunDir)));
  return skyLight(d) + sun * vec3(6.0, 5.6, 5.0);
}
