// @ts-check
// The hero's camera, shared by its shader and its hover readout: three views side by side, each a
// pinhole camera at the orbit position looking at a unit sphere at the origin (world up +y, as
// three.js's lookAt). Every pixel's ray meets the sphere analytically, so the JS readout and the
// picture agree on θ exactly, with no mesh and no depth buffer.
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { DEG } from '../../optics/angles.js';

export const FOV_DEG = 28; // vertical field of view of each view
export const VIEW_COUNT = 3;

/** @typedef {number[]} Vec3  [x, y, z] */

/** @type {(a: Vec3, b: Vec3) => number} */
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
/** @type {(a: Vec3, b: Vec3) => Vec3} */
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
/** @type {(a: Vec3) => Vec3} */
const unit = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };

/**
 * Eye position and camera basis for an orbit { azimuth, elevation (degrees), distance }.
 * @param {{ azimuth: number, elevation: number, distance: number }} view
 */
export function trioCamera(view) {
  const eye = directionFromAngles(view.azimuth, view.elevation).map((x) => x * view.distance);
  const forward = unit(eye.map((x) => -x));
  const right = unit(cross(forward, [0, 1, 0]));
  const up = cross(right, forward);
  return { eye, forward, right, up, tanHalfFov: Math.tan((FOV_DEG / 2) * DEG) };
}

/**
 * The unit ray through a point of one view, in that view's normalized coordinates (x, y in
 * [−1, 1], y up), for a view of the given width/height aspect.
 * @param {{ forward: Vec3, right: Vec3, up: Vec3, tanHalfFov: number }} camera  trioCamera()'s
 * @param {number} x
 * @param {number} y
 * @param {number} aspect
 */
export function rayThrough(camera, x, y, aspect) {
  const { forward, right, up, tanHalfFov } = camera;
  const sx = x * tanHalfFov * aspect;
  const sy = y * tanHalfFov;
  return unit([0, 1, 2].map((i) => forward[i] + sx * right[i] + sy * up[i]));
}

/**
 * Where a unit ray from the eye meets the unit sphere: |eye + t·d|² = 1 gives
 * t² + 2bt + c = 0 with b = eye·d and c = |eye|² − 1; the nearer root t = −b − √(b² − c).
 * Returns { normal, cosTheta } (cos θ between the normal and the direction to the eye), or null on a miss.
 * @param {Vec3} eye
 * @param {Vec3} dir  a unit vector
 */
export function hitSphere(eye, dir) {
  const b = dot(eye, dir);
  const h = b * b - (dot(eye, eye) - 1);
  if (h < 0) return null;
  const t = -b - Math.sqrt(h);
  const normal = [0, 1, 2].map((i) => eye[i] + t * dir[i]);
  return { normal, cosTheta: Math.min(1, Math.max(0, -dot(normal, dir))) };
}

/**
 * The square round each view's sphere, in drawing-buffer pixels [x, y, width, height] (origin
 * bottom left), clipped to its view: outside them every pixel is sky. The camera looks at the
 * sphere's centre, so its silhouette is a circle about the view's centre whose rays make the angle
 * α = asin(1/distance) with the axis: a radius of tan α / tan(fov/2) half-heights. A pixel belongs to
 * the view that spheres.frag.glsl gives it (floor of its centre over the view width); the margin
 * holds the anti-aliased rim, which reaches about a pixel past the silhouette.
 * @param {{ distance: number, tanHalfFov: number }} camera distance: |eye|
 * @param {number} width drawing-buffer pixels
 * @param {number} height
 * @param {number} count views side by side (1 or VIEW_COUNT)
 */
export function sphereSquares({ distance, tanHalfFov }, width, height, count, margin = 3) {
  const radius = (Math.tan(Math.asin(Math.min(1, 1 / distance))) / tanHalfFov) * (height / 2) + margin;
  const viewWidth = width / count;
  // Pixel x has its centre x + 0.5 in view floor((x + 0.5) / viewWidth) (the last view takes the rest).
  /** @param {number} slot */
  const firstPixel = (slot) => (slot >= count ? width : Math.max(0, Math.ceil(slot * viewWidth - 0.5)));
  const squares = [];
  for (let slot = 0; slot < count; slot += 1) {
    const cx = (slot + 0.5) * viewWidth;
    const x0 = Math.max(firstPixel(slot), Math.floor(cx - radius - 0.5));
    const x1 = Math.min(firstPixel(slot + 1), Math.ceil(cx + radius + 0.5));
    const y0 = Math.max(0, Math.floor(height / 2 - radius - 0.5));
    const y1 = Math.min(height, Math.ceil(height / 2 + radius + 0.5));
    if (x1 > x0 && y1 > y0) squares.push([x0, y0, x1 - x0, y1 - y0]);
  }
  return squares;
}
