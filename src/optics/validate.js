// Argument checks shared by every optics function: bad input is a RangeError naming the
// argument, never a NaN that travels on into a plot or a shader uniform.

/**
 * Returns cos θ clamped to [0, 1]; throws when it is not a finite number.
 * @param {number} value
 */
export function checkCos(value, name = 'cosThetaI') {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new RangeError(`${name} must be a finite number, got ${String(value)}`);
  }
  // Interpolated normals overshoot 1 by an ulp or dip below 0; clamp as production shaders do.
  return Math.min(1, Math.max(0, value));
}

/**
 * Throws unless the value is a finite number > 0 (a refractive index).
 * @param {number} value
 * @param {string} name
 */
export function checkIndex(value, name) {
  if (typeof value !== 'number' || !Number.isFinite(value) || value <= 0) {
    throw new RangeError(`${name} must be a finite number > 0, got ${String(value)}`);
  }
  return value;
}

/**
 * Throws unless the value is a finite number >= 0 (an extinction coefficient k).
 * @param {number} value
 */
export function checkExtinction(value, name = 'k') {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < 0) {
    throw new RangeError(`${name} must be a finite number >= 0, got ${String(value)}`);
  }
  return value;
}

/**
 * Clamps a result into [0, 1]; rounding can step one ulp outside.
 * @param {number} x
 */
export function unit(x) {
  return x <= 0 ? 0 : x >= 1 ? 1 : x;
}
