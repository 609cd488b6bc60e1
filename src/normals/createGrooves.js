// Grooves / ridges: a 1-D profile repeated `frequency` times across the tile.
// profile 'v': V-grooves, planar facets at exactly ±θ. Two facets average to (0, 0, cos θ), so the
// renormalized mip is flat and the true NDF is two spikes (Han et al.,
// "Frequency Domain Normal Map Filtering", SIGGRAPH 2007, Fig. 1).
// profile 'sine': smooth ridges h ∝ sin, slope tan θ · cos(2πt): a 1-D slope distribution that
// only LEAN renders anisotropic (Olano & Baker, "LEAN Mapping", I3D 2010).
import { checkFrequency, checkRange, degToRad, fract, makeMap } from './mapMath.js';

const DIRECTIONS = {
  u: [1, 0], // the profile varies along u: grooves run along v
  v: [0, 1],
  diagonal: [1, 1], // wave vector (f, f): still tileable
};

/**
 * createGrooves({ frequency = 16, angleDeg = 20, profile = 'v', direction = 'u' }).
 * With wave vector k = frequency·DIRECTIONS[direction] and phase t = fract(k·(u, v)), the slope is
 * b = s(t)·k/|k| with s = +tan θ for t < ½ and −tan θ after ('v'; the groove bottom is at t = ½,
 * the ridge at t = 0), or s = tan θ·cos(2πt) ('sine'). Texel centres at t = ¼, ¾ (period of 2^k
 * texels) never sit on a crease.
 */
export function createGrooves({ frequency = 16, angleDeg = 20, profile = 'v', direction = 'u' } = {}) {
  checkFrequency(frequency);
  checkRange(angleDeg, 0, 80, 'angleDeg');
  if (profile !== 'v' && profile !== 'sine') throw new RangeError(`profile must be 'v' or 'sine', got ${profile}`);
  const dir = DIRECTIONS[direction];
  if (!dir) throw new RangeError(`direction must be one of ${Object.keys(DIRECTIONS).join(', ')}, got ${direction}`);
  const kx = frequency * dir[0];
  const ky = frequency * dir[1];
  const len = Math.hypot(dir[0], dir[1]);
  const dx = dir[0] / len;
  const dy = dir[1] / len;
  const tanT = Math.tan(degToRad(angleDeg));
  const params = { frequency, angleDeg, profile, direction };
  const isV = profile === 'v';
  return makeMap('grooves', params, (u, v, out = [0, 0]) => {
    const t = fract(kx * u + ky * v);
    const s = isV ? (t < 0.5 ? tanT : -tanT) : tanT * Math.cos(2 * Math.PI * t);
    out[0] = s * dx;
    out[1] = s * dy;
    return out;
  });
}
