// Value noise (fBm of lattice value noise) with analytic derivatives: broadband detail whose
// variance leaks out one octave per mip, the realistic case.
// One octave: random values on an integer lattice, blended with Perlin's quintic fade
// f(t) = 6t⁵ − 15t⁴ + 10t³, f'(t) = 30t²(t − 1)² (Perlin, "Improving Noise", SIGGRAPH 2002), so the
// gradient is continuous. For corners a, b (x), c, d (y) and k = a − b − c + d:
//   N = a + (b − a)fx + (c − a)fy + k·fx·fy,
//   ∂N/∂x = fx'·(b − a + k·fy),  ∂N/∂y = fy'·(c − a + k·fx)
// (the analytic derivative of bilinear value noise, I. Quilez, "Value noise derivatives",
// iquilezles.org/articles/morenoise). The lattice of octave o has period P_o = frequency·2^o and
// wraps mod P_o, so every octave tiles.
import { checkFrequency, checkRange, makeMap } from './mapMath.js';

// A 32-bit integer hash to [−1, 1] (multiply–xorshift mixing; any fixed mixing will do, it only
// has to be deterministic and well spread).
function latticeValue(i, j, seed) {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(j, 0x165667b1) ^ Math.imul(seed, 0x61c88647);
  h = Math.imul(h ^ (h >>> 15), 0x2c1b3c6d);
  h = Math.imul(h ^ (h >>> 12), 0x297a2d39);
  h ^= h >>> 15;
  return ((h >>> 0) / 4294967295) * 2 - 1;
}

function fade(t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

function fadeSlope(t) {
  const s = t * (t - 1);
  return 30 * s * s;
}

/**
 * createValueNoise({ frequency = 8, octaves = 3, gain = 0.5, amplitude = 0.1, seed = 1 }).
 * Height h = amplitude · Σ_o gain^o · N_o(P_o u, P_o v) / P_o, so octave o adds the slope
 * −amplitude·gain^o·∇N_o, whatever its frequency. |∂N/∂x| ≤ max f' · 2 = 1.875 · 2 = 3.75, so
 * each slope component stays below 3.75 · amplitude · Σ gain^o (0.66 with the defaults).
 */
export function createValueNoise({ frequency = 8, octaves = 3, gain = 0.5, amplitude = 0.1, seed = 1 } = {}) {
  checkFrequency(frequency);
  checkRange(octaves, 1, 8, 'octaves');
  checkRange(gain, 0, 1, 'gain');
  checkRange(amplitude, 0, 1, 'amplitude');
  if (!Number.isInteger(octaves) || !Number.isInteger(seed)) throw new RangeError('octaves and seed must be integers');
  const params = { frequency, octaves, gain, amplitude, seed };
  return makeMap('noise', params, (u, v, out = [0, 0]) => {
    let gx = 0;
    let gy = 0;
    let weight = amplitude;
    for (let o = 0; o < octaves; o++) {
      const P = frequency << o;
      const x = (u - Math.floor(u)) * P;
      const y = (v - Math.floor(v)) * P;
      const i = Math.min(P - 1, Math.floor(x));
      const j = Math.min(P - 1, Math.floor(y));
      const tx = x - i;
      const ty = y - j;
      const i1 = i + 1 === P ? 0 : i + 1;
      const j1 = j + 1 === P ? 0 : j + 1;
      const s = seed + o * 7919;
      const a = latticeValue(i, j, s);
      const b = latticeValue(i1, j, s);
      const c = latticeValue(i, j1, s);
      const d = latticeValue(i1, j1, s);
      const k = a - b - c + d;
      gx += weight * fadeSlope(tx) * (b - a + k * fade(ty));
      gy += weight * fadeSlope(ty) * (c - a + k * fade(tx));
      weight *= gain;
    }
    out[0] = -gx;
    out[1] = -gy;
    return out;
  });
}

/** The height itself (same sum), for tests that check the slope is −∇h by finite differences. */
export function valueNoiseHeight({ frequency = 8, octaves = 3, gain = 0.5, amplitude = 0.1, seed = 1 } = {}, u, v) {
  let h = 0;
  let weight = amplitude;
  for (let o = 0; o < octaves; o++) {
    const P = frequency << o;
    const x = (u - Math.floor(u)) * P;
    const y = (v - Math.floor(v)) * P;
    const i = Math.min(P - 1, Math.floor(x));
    const j = Math.min(P - 1, Math.floor(y));
    const s = seed + o * 7919;
    const a = latticeValue(i, j, s);
    const b = latticeValue((i + 1) % P, j, s);
    const c = latticeValue(i, (j + 1) % P, s);
    const d = latticeValue((i + 1) % P, (j + 1) % P, s);
    const fx = fade(x - i);
    const fy = fade(y - j);
    h += (weight * (a + (b - a) * fx + (c - a) * fy + (a - b - c + d) * fx * fy)) / P;
    weight *= gain;
  }
  return h;
}
