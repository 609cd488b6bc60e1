// refraction-waves: the s-polarized field (E out of the screen) of a plane wave meeting the
// interface y = 0, medium n1 above, n2 below; lengths in vacuum wavelengths λ0. Every wave vector
// and amplitude comes from src/optics/waves.js as uniforms; this only evaluates
// field = Re{A·exp(i(k·r − ωt))} and draws the bright half of each wave (its crests).
// Phase continuity: all waves share kx along the interface, and t = 1 + r, so the field above and
// below agree at y = 0 (with the reflected wave shown).
precision highp float;

in vec2 vUv;
out vec4 fragColor;
uniform vec2 uResolution;
uniform float uHalfHeight;   // half the view height, in λ0
uniform float uKx;           // wave-vector component along the interface (same in both media)
uniform float uK1y;          // |normal component| in medium 1
uniform float uK2y;          // |normal component| in medium 2 (transmitted wave)
uniform float uKappa;        // evanescent decay rate; > 0 only under total internal reflection
uniform vec2 uR;             // complex reflection amplitude r_s
uniform vec2 uT;             // complex transmission amplitude t_s = 1 + r_s
uniform float uPhase;        // ωt, radians
uniform bool uShowReflected;
uniform vec2 uDirI;          // unit propagation directions for the rays: incident,
uniform vec2 uDirR;          // reflected,
uniform vec2 uDirT;          // transmitted (unused under total internal reflection)
uniform float uRayLength;

// Re{z·exp(iφ)} for a complex amplitude z = (re, im).
float re(vec2 z, float phi) {
  return z.x * cos(phi) - z.y * sin(phi);
}

// Distance from p to the segment a→b (world units).
float segmentDistance(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float h = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return length(p - a - h * ab);
}

// Coverage of a line of half-width `w` pixels at distance d (px: world units per pixel).
float coverage(float d, float w, float px) {
  return clamp(w - d / px + 0.5, 0.0, 1.0);
}

// Distance from p to a ray from `from` to `to` with an arrowhead at `to`.
float arrowDistance(vec2 p, vec2 from, vec2 to) {
  vec2 d = normalize(to - from);
  vec2 side = vec2(-d.y, d.x);
  float head = 0.32;
  float a = segmentDistance(p, from, to);
  a = min(a, segmentDistance(p, to, to - head * (d + 0.55 * side)));
  return min(a, segmentDistance(p, to, to - head * (d - 0.55 * side)));
}

// Distance to the rays drawn: incident always, reflected when shown (always under total internal
// reflection), transmitted unless there is none. Coverage falls with distance, so the coverage of
// the nearest ray is the largest, and one distance serves the ray and its wider dark outline.
float rayDistance(vec2 p, float px) {
  // Every ray and arrowhead lies within uRayLength + head·|(1, 0.55)| < uRayLength + 0.4 of the
  // origin: farther than the outline reaches (4.5 px) beyond that, nothing is covered.
  if (length(p) - (uRayLength + 0.4) > 5.0 * px) return 1e9;
  float rays = arrowDistance(p, -uRayLength * uDirI, vec2(0.0));
  if (uShowReflected || uKappa > 0.0) rays = min(rays, arrowDistance(p, vec2(0.0), uRayLength * uDirR));
  if (uKappa == 0.0) rays = min(rays, arrowDistance(p, vec2(0.0), uRayLength * uDirT));
  return rays;
}

void main() {
  float px = 2.0 * uHalfHeight / uResolution.y;
  vec2 p = (vUv * 2.0 - 1.0) * vec2(uHalfHeight * uResolution.x / uResolution.y, uHalfHeight);
  float along = uKx * p.x - uPhase;

  float field;
  vec3 dark;
  vec3 crest;
  if (p.y >= 0.0) {
    field = cos(along - uK1y * p.y);                                  // incident, travelling down
    if (uShowReflected) field += re(uR, along + uK1y * p.y);          // reflected, travelling up
    dark = vec3(0.04, 0.07, 0.13);
    crest = vec3(0.45, 0.78, 1.0);
  } else if (uKappa > 0.0) {
    field = exp(uKappa * p.y) * re(uT, along);                        // evanescent: no wave travels down
    dark = vec3(0.10, 0.06, 0.02);
    crest = vec3(1.0, 0.78, 0.40);
  } else {
    field = re(uT, along - uK2y * p.y);                               // transmitted, travelling down
    dark = vec3(0.10, 0.06, 0.02);
    crest = vec3(1.0, 0.78, 0.40);
  }
  vec3 colour = mix(dark, crest, clamp(field, 0.0, 1.0)) + 0.35 * clamp(field - 1.0, 0.0, 1.0);

  // The interface, the normal (dashed) and the rays through the origin.
  colour = mix(colour, vec3(0.8), coverage(segmentDistance(p, vec2(-1e3, 0.0), vec2(1e3, 0.0)), 1.2, px));
  float dash = step(0.5, fract(p.y * 2.5));
  colour = mix(colour, vec3(0.6), dash * coverage(segmentDistance(p, vec2(0.0, -uHalfHeight), vec2(0.0, uHalfHeight)), 1.0, px));
  float near = rayDistance(p, px);
  float rays = coverage(near, 2.0, px);
  colour = mix(colour, vec3(0.0), 0.8 * (coverage(near, 4.0, px) - rays));
  colour = mix(colour, vec3(1.0), rays);
  fragColor = vec4(colour, 1.0);
}
