// A light or view direction from the azimuth and elevation the controls show.
import { DEG } from '../optics/angles.js';

/** Unit vector [x, y, z] for azimuth/elevation in degrees (azimuth 0 looks from +z, the default camera side). */
export function directionFromAngles(azimuthDeg, elevationDeg) {
  const az = azimuthDeg * DEG;
  const el = elevationDeg * DEG;
  return [Math.cos(el) * Math.sin(az), Math.sin(el), Math.cos(el) * Math.cos(az)];
}
