// Two unit spheres side by side, one in each half of the canvas, each seen from the same camera
// placement and ray-cast analytically (no mesh): the normal is exact, and the centre of each half
// looks straight at its sphere's centre (θ = 0). Used by the fresnel-lighting and metals panels;
// the camera numbers come from src/panels/shared/createTwinStage.js, which also maps θ to pixels.
uniform vec2 uResolution; // drawing-buffer pixels
uniform vec3 uCamera;     // (distance to the sphere centre, focal length, elevation in radians)
uniform float uStacked;   // 1: one sphere above the other (a phone), each in a 4:3 half; 0: side by side

struct StageHit {
  bool found;
  int side;    // 0 = left half, 1 = right half
  vec3 dir;    // the eye ray (for the background when nothing is hit)
  vec3 normal;
  vec3 view;   // unit vector from the surface to the eye
};

StageHit castStage() {
  StageHit hit;
  vec2 centre;
  float scale; // half the height of this sphere's half
  if (uStacked > 0.5) {
    float halfHeight = 0.5 * uResolution.y;
    hit.side = gl_FragCoord.y >= halfHeight ? 0 : 1; // the first sphere on top
    centre = vec2(0.5 * uResolution.x, (hit.side == 0 ? 1.5 : 0.5) * halfHeight);
    scale = 0.5 * halfHeight;
  } else {
    float halfWidth = 0.5 * uResolution.x;
    hit.side = gl_FragCoord.x >= halfWidth ? 1 : 0;
    centre = vec2((float(hit.side) + 0.5) * halfWidth, 0.5 * uResolution.y);
    scale = 0.5 * uResolution.y;
  }
  // Pixel offset from the centre of this half, in units of half its height.
  vec2 ndc = (gl_FragCoord.xy - centre) / scale;
  float elevation = uCamera.z;
  vec3 eye = uCamera.x * vec3(0.0, sin(elevation), cos(elevation));
  vec3 forward = -normalize(eye);
  vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
  vec3 up = cross(right, forward);
  hit.dir = normalize(uCamera.y * forward + ndc.x * right + ndc.y * up);
  // |eye + t·dir|² = 1: t² + 2bt + c = 0 with b = eye·dir, c = |eye|² − 1; the nearer root.
  float b = dot(eye, hit.dir);
  float h = b * b - (dot(eye, eye) - 1.0);
  hit.found = h >= 0.0;
  float t = -b - sqrt(max(h, 0.0));
  hit.normal = normalize(eye + t * hit.dir);
  hit.view = -hit.dir;
  return hit;
}
