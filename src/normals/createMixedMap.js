// Mixed map: a blocks × blocks grid of regions, each flat, bumps, grooves, slope checker or value
// noise, so per-texel gloss varies across the map (like the RenderMonkey map of Hill's "Specular
// Showdown", 2011, chosen for its mix of rough and smooth areas). The child maps have periods that
// divide the block side, so each block holds whole periods; region borders are creases, as in a
// painted map.
import { createBumps } from './createBumps.js';
import { createGrooves } from './createGrooves.js';
import { createSlopeChecker } from './createSlopeChecker.js';
import { createValueNoise } from './createValueNoise.js';
import { checkFrequency, makeMap } from './mapMath.js';

/** Region kinds, indexed by (bi + 2·bj) mod 5: every row and column mixes four of them. */
export const MIXED_REGIONS = Object.freeze(['flat', 'bumps', 'grooves', 'checker', 'noise']);

/**
 * createMixedMap({ blocks = 4, frequency = 2, angleDeg = 20, edgeAngleDeg = 45, amplitude = 0.1,
 * seed = 1 }). frequency counts features per block: bumps and noise lattice cells `frequency`,
 * grooves 2·frequency periods, checker 4·frequency cells. Grooves run along v in even block rows
 * and along u in odd ones, so both orientations of the anisotropy appear.
 * The map also has regionAt(u, v) → one of MIXED_REGIONS.
 */
export function createMixedMap({ blocks = 4, frequency = 2, angleDeg = 20, edgeAngleDeg = 45, amplitude = 0.1, seed = 1 } = {}) {
  checkFrequency(blocks, 'blocks');
  checkFrequency(frequency);
  const f = blocks * frequency;
  const children = {
    bumps: createBumps({ frequency: f, edgeAngleDeg }),
    groovesU: createGrooves({ frequency: 2 * f, angleDeg, direction: 'u' }),
    groovesV: createGrooves({ frequency: 2 * f, angleDeg, direction: 'v' }),
    checker: createSlopeChecker({ frequency: 4 * f, angleDeg }),
    noise: createValueNoise({ frequency: f, amplitude, seed }),
  };
  const blockOf = (x) => Math.floor((x - Math.floor(x)) * blocks) % blocks;
  const regionAt = (u, v) => MIXED_REGIONS[(blockOf(u) + 2 * blockOf(v)) % MIXED_REGIONS.length];
  const params = { blocks, frequency, angleDeg, edgeAngleDeg, amplitude, seed };
  const map = makeMap('mixed', params, (u, v, out = [0, 0]) => {
    const region = regionAt(u, v);
    if (region === 'flat') {
      out[0] = 0;
      out[1] = 0;
      return out;
    }
    const child = region === 'grooves' ? (blockOf(v) & 1 ? children.groovesV : children.groovesU) : children[region];
    return child.slopeAt(u, v, out);
  });
  return Object.freeze({ ...map, regionAt });
}
