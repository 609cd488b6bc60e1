// Every distinct parameter set a homework question's generator gives, over many seeds: the tests
// that recompute a question's numbers check each set a student can be given, not one example.
import { seededRandom } from '../../src/homework/seededRandom.js';

/**
 * The distinct parameter sets of `q` over 400 seeds named `${prefix}-0` … `${prefix}-399`.
 * @param {{ params: (rng: ReturnType<typeof seededRandom>) => unknown }} q
 * @param {string} prefix
 */
export function allParams(q, prefix) {
  const seen = new Map();
  for (let seed = 0; seed < 400; seed += 1) {
    const p = q.params(seededRandom(`${prefix}-${seed}`));
    seen.set(JSON.stringify(p), p);
  }
  return [...seen.values()];
}
