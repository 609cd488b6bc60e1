// Options for the property tests (tests/unit/*.property.test.js). Runs stay short in
// `npm run test:unit`; FUZZ_RUNS=5000 searches harder. A failure prints its seed and path:
// FUZZ_SEED=<seed> FUZZ_PATH=<path> npx vitest run <file> replays exactly that case.
import fc from 'fast-check';
import { vi } from 'vitest';

const env = globalThis.process?.env ?? {};
const runs = Number.parseInt(env.FUZZ_RUNS ?? '', 10);
if (runs > 0) vi.setConfig({ testTimeout: 10_000 + 50 * runs }); // a long search is not a hung test

/** fast-check's parameters: numRuns (FUZZ_RUNS, else `defaultRuns`), and the seed and path to replay. */
export function fuzzOptions(defaultRuns = 150) {
  return {
    numRuns: Number.isInteger(runs) && runs > 0 ? runs : defaultRuns,
    ...(env.FUZZ_SEED ? { seed: Number(env.FUZZ_SEED) } : {}),
    ...(env.FUZZ_PATH ? { path: env.FUZZ_PATH } : {}),
  };
}

/** fc.assert with those options. */
export function check(property, defaultRuns) {
  fc.assert(property, fuzzOptions(defaultRuns));
}
