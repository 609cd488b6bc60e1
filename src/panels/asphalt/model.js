// The asphalt scene in float64: camera, sun and the shading of the road's mean (flat) surface.
// Pure math, no DOM: the panel's numbers, its hover readout and its tests come from here, and the
// shader (asphalt.frag.glsl) receives these same constants as uniforms.
import { fresnelExact, normalIncidence } from '../../optics/fresnel.js';
import { microfacetSpecular } from '../../optics/microfacet.js';
import { DEG } from '../../optics/angles.js';


export const SCENE = {
  fovY: 40, // vertical field of view, degrees
  cameraHeight: 1.5, // metres above the road (eye height)
  sun: [3.6, 3.3, 2.9], // sun irradiance on a surface facing it, linear RGB (warm, low sun)
  ambient: [0.16, 0.2, 0.27], // sky irradiance on the road / π, linear RGB (blue sky)
  albedo: 0.09, // mean road albedo: dark bitumen with lighter aggregate (fresh asphalt ~0.05, worn ~0.12)
  exposure: 2.5, // scene-to-display scale before the tone curve 1 − exp(−x)
};

/** Relative luminance of linear Rec. 709 RGB (ITU-R BT.709 weights). */
export function luminance([r, g, b]) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

const SUN_Y = luminance(SCENE.sun);
const AMBIENT_Y = luminance(SCENE.ambient);

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (v) => {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
};

/** The camera looks towards +z, pitched down by its elevation; the sun is ahead of it. */
export function cameraBasis(camElDeg) {
  const e = camElDeg * DEG;
  const forward = [0, -Math.sin(e), Math.cos(e)];
  const up = [0, Math.cos(e), Math.sin(e)];
  return { forward, up, right: [-1, 0, 0] }; // right = forward × up
}

/** Unit vector towards the sun at this elevation, straight ahead of the camera. */
export function sunDirection(sunElDeg) {
  const e = sunElDeg * DEG;
  return [0, Math.sin(e), Math.cos(e)];
}

/** The view ray through normalized device coordinates (−1..1 both ways, y up). */
export function pixelRay(camElDeg, ndcX, ndcY, aspect) {
  const { forward, up, right } = cameraBasis(camElDeg);
  const t = Math.tan((SCENE.fovY / 2) * DEG);
  const x = ndcX * t * aspect;
  const y = ndcY * t;
  return normalize([0, 1, 2].map((i) => forward[i] + x * right[i] + y * up[i]));
}

/**
 * Shading of the flat road seen along `dir` (from the camera): the half-vector angle θd between the
 * light and h, F there (exact, from air n_i = 1 into the binder's n_t), and the luminance of the specular and diffuse
 * parts. Specular radiance L = f·E·cosθl with f the GGX Cook–Torrance BRDF (src/optics/microfacet.js);
 * with Fresnel off, F is the constant R0. Diffuse is Lambert: albedo·(E·cosθl/π + ambient).
 * Returns null when the ray does not meet the road.
 */
export function shadeRoad(dir, { sunEl, roughness, nT, fresnel }) {
  if (!(dir[1] < 0)) return null;
  const v = [-dir[0], -dir[1], -dir[2]];
  const l = sunDirection(sunEl);
  const h = normalize([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
  const cosD = Math.min(1, Math.max(0, dot(l, h)));
  const F = fresnel ? fresnelExact(cosD, 1, nT) : normalIncidence(1, nT);
  const cosL = l[1];
  const f = microfacetSpecular({ cosL, cosV: v[1], cosH: h[1], alpha: roughness * roughness, F });
  const specular = f * SUN_Y * Math.max(0, cosL);
  const diffuse = SCENE.albedo * (SUN_Y * Math.max(0, cosL) / Math.PI + AMBIENT_Y);
  const distance = SCENE.cameraHeight / -dir[1];
  return { thetaD: Math.acos(cosD) / DEG, F, specular, diffuse, distance };
}

/** The tone curve of the shader, 1 − exp(−exposure·x), on a luminance. */
export function displayed(x) {
  return 1 - Math.exp(-SCENE.exposure * x);
}

/**
 * The brightest highlight in view: a scan of the central column (the sun is straight ahead, so by
 * symmetry the peak lies on it): the road rows of that column, the brightest of them, and the
 * view centre's shading.
 */
export function highlightInView(values, aspect, rows = 241) {
  const column = [];
  let peak = null;
  for (let i = 0; i < rows; i += 1) {
    const ndcY = -1 + (2 * i) / (rows - 1);
    const hit = shadeRoad(pixelRay(values.camEl, 0, ndcY, aspect), values);
    if (!hit) continue;
    column.push({ ...hit, ndcY });
    if (!peak || hit.specular > peak.specular) peak = column.at(-1);
  }
  const centre = shadeRoad(pixelRay(values.camEl, 0, 0, aspect), values);
  return { peak, centre, column };
}
