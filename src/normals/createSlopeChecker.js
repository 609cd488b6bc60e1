// Slope checker: a frequency × frequency checkerboard of planar facets tilted by +θ and −θ in the
// azimuth φ: a 2-D form of the V-groove (Han et al., "Frequency Domain Normal Map Filtering",
// SIGGRAPH 2007, Fig. 1). Any 2×2 block of cells averages to
// (0, 0, cos θ) exactly, so mip 1 of a 2-texel checker is flat and short, and renormalized mips
// are a mirror: the worst case. It is a normal map, not a height field: facets of opposite tilt
// meet at steps (like many painted normal maps); only the normals matter here.
import { checkFrequency, checkRange, degToRad, makeMap } from './mapMath.js';

/** createSlopeChecker({ frequency = 32, angleDeg = 20, azimuthDeg = 45 }); frequency is even, so the tile repeats. */
export function createSlopeChecker({ frequency = 32, angleDeg = 20, azimuthDeg = 45 } = {}) {
  if (checkFrequency(frequency) % 2) throw new RangeError(`checker frequency must be even to tile, got ${frequency}`);
  checkRange(angleDeg, 0, 80, 'angleDeg');
  checkRange(azimuthDeg, -360, 360, 'azimuthDeg');
  const t = Math.tan(degToRad(angleDeg));
  const phi = degToRad(azimuthDeg);
  const bx = t * Math.cos(phi);
  const by = t * Math.sin(phi);
  return makeMap('checker', { frequency, angleDeg, azimuthDeg }, (u, v, out = [0, 0]) => {
    const odd = (Math.floor(u * frequency) + Math.floor(v * frequency)) & 1;
    out[0] = odd ? -bx : bx;
    out[1] = odd ? -by : by;
    return out;
  });
}
