// Angles: the panels speak degrees, the formulas radians. One constant and two conversions, so
// no file declares its own (and none mistakes 180/π for π/180).

/** Radians per degree: θ in radians is θ° · DEG. */
export const DEG = Math.PI / 180;

/**
 * Radians to degrees.
 * @param {number} radians
 */
export function toDegrees(radians) {
  return radians / DEG;
}

/**
 * cos θ for θ in degrees, with cos 90° exactly 0 (Math.cos(π/2) is 6e-17 in float64, not 0).
 * @param {number} thetaDeg
 */
export function cosDeg(thetaDeg) {
  return thetaDeg >= 90 ? 0 : Math.cos(thetaDeg * DEG);
}
