// Shared math of the procedural normal maps: height fields with analytic derivatives, so the
// reference normal is exact at any sub-texel position.
// Every map is a slope field b(u, v) = −∇h(u, v) over the unit tile (u, v ∈ [0, 1), period 1),
// with heights in tile units. b is LEAN's B = (n_x/n_z, n_y/n_z) (Olano & Baker, "LEAN Mapping",
// I3D 2010), and the tangent-space normal is n = normalize(b_x, b_y, 1), i.e.
// normalize(−∂h/∂u, −∂h/∂v, 1) with +Y up, the OpenGL convention of three.js and glTF (glTF 2.0
// spec, material.normalTexture: "+X is right and +Y is up").

import { DEG } from '../optics/angles.js';

export function fract(x) {
  return x - Math.floor(x);
}

export function degToRad(deg) {
  return deg * DEG;
}

/** Writes the unit normal of slope (bx, by) into out and returns it. */
export function slopeToNormal(bx, by, out = [0, 0, 0]) {
  const inv = 1 / Math.sqrt(1 + bx * bx + by * by);
  out[0] = bx * inv;
  out[1] = by * inv;
  out[2] = inv;
  return out;
}

/** Throws unless value is an integer ≥ 1: a tile must hold a whole number of periods. */
export function checkFrequency(value, name = 'frequency') {
  if (!Number.isInteger(value) || value < 1) {
    throw new RangeError(`${name} must be an integer >= 1 (tileable), got ${String(value)}`);
  }
  return value;
}

/** Throws unless lo <= value <= hi. */
export function checkRange(value, lo, hi, name) {
  if (typeof value !== 'number' || !(value >= lo && value <= hi)) {
    throw new RangeError(`${name} must be in [${lo}, ${hi}], got ${String(value)}`);
  }
  return value;
}

/**
 * Wraps a slope function into the map object every consumer uses:
 * { kind, params, slopeAt(u, v, out = [bx, by]), normalAt(u, v, out = [x, y, z]) }.
 * Both write into out (no allocation in the samplers' inner loops) and return it.
 */
export function makeMap(kind, params, slopeAt) {
  const scratch = [0, 0];
  return Object.freeze({
    kind,
    params: Object.freeze({ ...params }),
    slopeAt,
    normalAt(u, v, out = [0, 0, 0]) {
      slopeAt(u, v, scratch);
      return slopeToNormal(scratch[0], scratch[1], out);
    },
  });
}
