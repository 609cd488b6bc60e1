// The asphalt scene in float64: camera, sun and the shading of the road's mean (flat) surface.
// Pure math, no DOM: the panel's numbers, its hover readout and its tests come from here, and the
// shader (asphalt.frag.glsl) receives these same constants as uniforms.
import { fresnelExact, normalIncidence } from '../../optics/fresnel.js';
import { microfacetSpecular, smithG2 } from '../../optics/microfacet.js';
import { DEG } from '../../optics/angles.js';
import { luminance } from '../../optics/luminance.js';
import { refinedMax } from '../../optics/refinedMax.js';


export const SCENE = {
  fovY: 40, // vertical field of view, degrees
  cameraHeight: 1.5, // metres above the road (eye height)
  sun: [3.6, 3.3, 2.9], // sun irradiance on a surface facing it, linear RGB (warm, low sun)
  ambient: [0.16, 0.2, 0.27], // sky irradiance on the road / π, linear RGB (blue sky)
  albedo: 0.09, // mean road albedo: dark bitumen with lighter aggregate (fresh asphalt ~0.05, worn ~0.12)
  exposure: 2.5, // scene-to-display scale before the tone curve 1 − exp(−x)
};


const SUN_Y = luminance(SCENE.sun);
const AMBIENT_Y = luminance(SCENE.ambient);

/** @typedef {readonly number[]} Vec3  x, y (up), z (towards the sun) */
/** @typedef {{ sunEl: number, roughness: number, nT: number, fresnel: boolean }} RoadValues  the panel's values shadeRoad reads */
/**
 * @typedef {{ thetaD: number, F: number, lobe: number, specular: number, diffuse: number, distance: number,
 *   below: number }} Shade  what shadeRoad returns
 */

const dot = (/** @type {Vec3} */ a, /** @type {Vec3} */ b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (/** @type {Vec3} */ v) => {
  const l = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / l, v[1] / l, v[2] / l];
};

/**
 * The camera looks towards +z, pitched down by its elevation; the sun is ahead of it.
 * @param {number} camElDeg
 */
export function cameraBasis(camElDeg) {
  const e = camElDeg * DEG;
  const forward = [0, -Math.sin(e), Math.cos(e)];
  const up = [0, Math.cos(e), Math.sin(e)];
  return { forward, up, right: [-1, 0, 0] }; // right = forward × up
}

/**
 * Unit vector towards the sun at this elevation, straight ahead of the camera.
 * @param {number} sunElDeg
 */
export function sunDirection(sunElDeg) {
  const e = sunElDeg * DEG;
  return [0, Math.sin(e), Math.cos(e)];
}

/**
 * The view ray through normalized device coordinates (−1..1 both ways, y up).
 * @param {number} camElDeg
 * @param {number} ndcX
 * @param {number} ndcY
 * @param {number} aspect
 */
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
 * parts. Specular radiance L = f·E·cosθl with f the GGX Cook–Torrance BRDF (src/optics/microfacet.js),
 * kept as its two factors: `lobe` = D·G2/(4 cosθl cosθv), where the rough facets send the light, and F.
 * With Fresnel off, F is the constant R0. Diffuse is Lambert: albedo·(E·cosθl/π + ambient).
 * `below` is how far below the horizon the spot is seen, in degrees: on a flat road under a far sun
 * and sky, what a spot sends towards the eye depends on that direction alone, not on the camera.
 * Returns null when the ray does not meet the road.
 * @param {Vec3} dir
 * @param {RoadValues} values
 * @returns {Shade | null}
 */
export function shadeRoad(dir, { sunEl, roughness, nT, fresnel }) {
  if (!(dir[1] < 0)) return null;
  const v = [-dir[0], -dir[1], -dir[2]];
  const l = sunDirection(sunEl);
  const h = normalize([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
  const cosD = Math.min(1, Math.max(0, dot(l, h)));
  const F = fresnel ? fresnelExact(cosD, 1, nT) : normalIncidence(1, nT);
  const cosL = l[1];
  const lobe = microfacetSpecular({ cosL, cosV: v[1], cosH: h[1], alpha: roughness * roughness, F: 1 });
  const specular = lobe * F * SUN_Y * Math.max(0, cosL);
  const diffuse = SCENE.albedo * (SUN_Y * Math.max(0, cosL) / Math.PI + AMBIENT_Y);
  const distance = SCENE.cameraHeight / -dir[1];
  const below = Math.asin(Math.min(1, -dir[1])) / DEG;
  return { thetaD: Math.acos(cosD) / DEG, F, lobe, specular, diffuse, distance, below };
}

/**
 * The tone curve of the shader, 1 − exp(−exposure·x), on a luminance.
 * @param {number} x
 */
export function displayed(x) {
  return 1 - Math.exp(-SCENE.exposure * x);
}

/**
 * The brightest highlight in view: a scan of the central column (the sun is straight ahead, so by
 * symmetry the peak lies on it), its brightest row refined between its grid neighbours
 * (refinedMax.js) so the numbers shown of it hold, and the view centre's shading.
 * @param {RoadValues & { camEl: number }} values
 * @param {number} aspect
 */
export function highlightInView(values, aspect, rows = 241) {
  const column = [];
  const ys = [];
  const speculars = [];
  const at = (/** @type {number} */ ndcY) => shadeRoad(pixelRay(values.camEl, 0, ndcY, aspect), values);
  for (let i = 0; i < rows; i += 1) {
    const ndcY = -1 + (2 * i) / (rows - 1);
    const hit = at(ndcY);
    ys.push(ndcY);
    speculars.push(hit ? hit.specular : 0);
    if (hit) column.push({ ...hit, ndcY });
  }
  const best = refinedMax(ys, speculars, (y) => at(y)?.specular ?? 0);
  const peak = at(best.theta);
  // Every camera elevation of the schema (2° to 90° down) sees the road in the lower half of the view.
  if (!peak) throw new RangeError(`no road in view from ${values.camEl}° down`);
  const centre = at(0);
  return { peak: { ...peak, ndcY: best.theta }, centre, column };
}

/**
 * The radiance of a matte (Lambertian) road that reflected the same share `albedo` of the sunlight,
 * albedo·E·cosθl/π, the same from every direction: what the specular layer's brightest spot is set
 * against to say whether its light is concentrated.
 * @param {number} albedo
 * @param {number} sunEl
 */
export function lambertianEquivalent(albedo, sunEl) {
  return (albedo * SUN_Y * Math.max(0, Math.sin(sunEl * DEG))) / Math.PI;
}

/**
 * The line of sight `belowDeg` below the horizon, straight towards the sun (the camera's +z).
 * @param {number} belowDeg
 */
export function sightBelow(belowDeg) {
  const b = belowDeg * DEG;
  return [0, -Math.sin(b), Math.cos(b)];
}

/**
 * The shading of the road seen `belowDeg` (in (0°, 180°)) below the horizon, which a sight line
 * that points down always meets.
 * @param {number} belowDeg
 * @param {RoadValues} values
 */
function shadeBelow(belowDeg, values) {
  const hit = shadeRoad(sightBelow(belowDeg), values);
  if (!hit) throw new RangeError(`a sight line ${belowDeg}° below the horizon misses the road`);
  return hit;
}

/**
 * The brightest the sun's highlight gets from any direction: the largest specular luminance over every
 * sight line below the horizon in the sun's vertical plane (belowDeg from 0°, the horizon limit, through
 * 90°, straight down, to 180°, looking away from the sun), refined off its 0.25° grid. By the plane's
 * mirror symmetry the lobe peaks in it (tests/unit/asphaltWords.test.js scans the whole hemisphere). It
 * depends on the sun and the road alone, not on the camera: how concentrated the reflected light is.
 * @param {RoadValues} values
 * @returns {{ below: number, specular: number }}
 */
export function brightestSightLine(values) {
  const EDGE = 1e-6; // a sight line along the road misses it; a hair below gives the limit
  const specularAt = (/** @type {number} */ b) => shadeBelow(Math.min(180 - EDGE, Math.max(EDGE, b)), values).specular;
  const grid = Array.from({ length: 721 }, (_, i) => i / 4);
  const best = refinedMax(grid, grid.map(specularAt), specularAt);
  return { below: Math.min(180 - EDGE, Math.max(EDGE, best.theta)), specular: best.value };
}

/** How far below the horizon sheenGrowth's reference spot is seen: the road straight below. */
export const STRAIGHT_DOWN = 90;

/**
 * How much brighter the sun's highlight at the brightest spot in view is than at the road seen
 * straight down, split into the two factors of the specular luminance E·cosθl·lobe·F (E·cosθl is
 * the same everywhere): the lobe D·G2/(4 cosθl cosθv) and F(θd). total = lobe × fresnel; overall
 * is the ratio of the whole luminance, the diffuse road counted too. Both spots are named by the
 * direction they are seen in, so the factors do not depend on the field of view.
 * @param {RoadValues & { camEl: number }} values
 * @param {number} aspect
 */
export function sheenGrowth(values, aspect) {
  const now = highlightInView(values, aspect).peak;
  const below = shadeBelow(STRAIGHT_DOWN, values);
  const lobe = now.lobe / below.lobe;
  const fresnel = now.F / below.F;
  const overall = (now.specular + now.diffuse) / (below.specular + below.diffuse);
  return { lobe, fresnel, total: lobe * fresnel, overall, spot: now, reference: below };
}

/**
 * The share of a sun-ward spot's light towards the eye that is specular, for the spot seen
 * `belowDeg` below the horizon: specular / (specular + diffuse) of its luminance; 1/2 where the
 * two are equal. A function of the direction alone (shadeRoad).
 * @param {RoadValues} values
 * @returns {(belowDeg: number) => number}
 */
export function specularShareBelow(values) {
  return (belowDeg) => {
    // At the horizon itself the sight line misses the road; a hair below it gives the limit.
    const hit = shadeBelow(Math.max(belowDeg, 1e-6), values);
    return hit.specular / (hit.specular + hit.diffuse);
  };
}

/**
 * u in [0, 1) where the increasing g(u) crosses `level`, by bisection.
 * @param {(u: number) => number} g
 * @param {number} level
 */
function crossing(g, level) {
  let lo = 0;
  let hi = 1;
  for (let i = 0; i < 60; i += 1) {
    const mid = (lo + hi) / 2;
    if (g(mid) < level) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

/**
 * The share of the sunlight falling on the road that its specular layer reflects, into all
 * directions: the directional albedo ∫ f cosθo dωo of the GGX BRDF for light at elevation sunEl.
 * Integrated over the half-vector h, whose GGX distribution maps u ∈ [0, 1) to
 * tan²θh = α²u/(1 − u) (Walter et al., EGSR 2007, eq. 35): with dωo = 4(o·h) dωh the integrand is
 * G2·F(θd)·(l·h)/(cosθl cosθh) (D cancels). For each θh the reflected direction o = 2(l·h)h − l
 * stays above the road for |φ| < φmax, cos φmax = e(u) = l_y(1 − 2cos²θh)/(2 l_z sinθh cosθh), which
 * grows with u: every φ below the u where e = −1, a part up to the u where e = 1, none past it.
 * The φ integral runs over its range alone, and the part-range stretch of u, where φmax has square-
 * root ends, is sampled through u = a + (b − a)(1 − cos πt)/2, which smooths them: midpoint sums then
 * converge fast (a unit test holds the result against a far finer grid).
 * @param {RoadValues} values
 */
export function specularAlbedo({ sunEl, roughness, nT, fresnel }, n = 64) {
  const l = sunDirection(sunEl);
  const alpha = roughness * roughness;
  const a2 = alpha * alpha;
  const r0 = normalIncidence(1, nT);
  const cosHAt = (/** @type {number} */ u) => 1 / Math.sqrt(1 + (a2 * u) / (1 - u));
  const edgeAt = (/** @type {number} */ u) => {
    const c = cosHAt(u);
    return (l[1] * (1 - 2 * c * c)) / (2 * l[2] * Math.sqrt((1 - c) * (1 + c)) * c);
  };
  // ∫ over |φ| < φmax of the integrand at u, divided by 2π.
  const ring = (/** @type {number} */ u) => {
    const cosH = cosHAt(u);
    const sinH = Math.sqrt((1 - cosH) * (1 + cosH));
    const edge = edgeAt(u);
    if (edge >= 1) return 0;
    const phiMax = edge <= -1 ? Math.PI : Math.acos(edge);
    let sum = 0;
    for (let j = 0; j < n; j += 1) {
      const cosD = l[1] * cosH + l[2] * sinH * Math.cos((phiMax * (j + 0.5)) / n);
      const cosO = Math.min(1, Math.max(0, 2 * cosD * cosH - l[1]));
      const F = fresnel ? fresnelExact(Math.min(1, cosD), 1, nT) : r0;
      sum += (smithG2(l[1], cosO, alpha) * F * cosD) / (l[1] * cosH);
    }
    return (sum * phiMax) / (Math.PI * n);
  };
  const full = crossing(edgeAt, -1);
  const none = crossing(edgeAt, 1);
  let total = 0;
  for (let i = 0; i < n; i += 1) total += (ring((full * (i + 0.5)) / n) * full) / n;
  for (let i = 0; i < n; i += 1) {
    const t = (i + 0.5) / n;
    const u = full + ((none - full) * (1 - Math.cos(Math.PI * t))) / 2;
    total += (ring(u) * (none - full) * Math.PI * Math.sin(Math.PI * t)) / (2 * n);
  }
  return total;
}
