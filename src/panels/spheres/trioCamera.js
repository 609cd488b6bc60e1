// @ts-check
// The hero's camera, shared by its shader and its hover readout: three views side by side, each a
// pinhole camera at the orbit position looking at a unit sphere at the origin (world up +y, as
// three.js's lookAt). Every pixel's ray meets the sphere analytically, so the JS readout and the
// picture agree on θ exactly, with no mesh and no depth buffer.
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { DEG } from '../../optics/angles.js';

export const FOV_DEG = 28; // vertical field of view of each view
export const VIEW_COUNT = 3;

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
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
 */
export function hitSphere(eye, dir) {
  const b = dot(eye, dir);
  const h = b * b - (dot(eye, eye) - 1);
  if (h < 0) return null;
  const t = -b - Math.sqrt(h);
  const normal = [0, 1, 2].map((i) => eye[i] + t * dir[i]);
  return { normal, cosTheta: Math.min(1, Math.max(0, -dot(normal, dir))) };
}
