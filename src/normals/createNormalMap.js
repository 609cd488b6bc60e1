// One entry point for the panel: createNormalMap(kind, params) for every procedural map kind.
// Each returns { kind, params, slopeAt(u, v, out), normalAt(u, v, out) } (see mapMath.js).
import { createBumps } from './createBumps.js';
import { createGrooves } from './createGrooves.js';
import { createMixedMap } from './createMixedMap.js';
import { createSlopeChecker } from './createSlopeChecker.js';
import { createValueNoise } from './createValueNoise.js';
import { makeMap } from './mapMath.js';

function createFlat() {
  return makeMap('flat', {}, (_u, _v, out = [0, 0]) => {
    out[0] = 0;
    out[1] = 0;
    return out;
  });
}

const FACTORIES = {
  bumps: createBumps,
  grooves: createGrooves,
  checker: createSlopeChecker,
  noise: createValueNoise,
  mixed: createMixedMap,
  flat: createFlat,
};

/** The kinds a panel offers: 'bumps', 'grooves', 'checker', 'noise', 'mixed', 'flat'. */
export const MAP_KINDS = Object.freeze(Object.keys(FACTORIES));

export function createNormalMap(kind, params = {}) {
  const factory = FACTORIES[kind];
  if (!factory) throw new RangeError(`unknown map kind ${String(kind)}; expected one of ${MAP_KINDS.join(', ')}`);
  return factory(params);
}
