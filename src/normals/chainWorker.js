// Dedicated worker: builds the normal-mips chains off the page's thread, so that a 512² or 1024²
// map (a few hundred ms of work) never blocks input. Each message { id, request } is answered
// { id, result } or { id, error }; the typed arrays are transferred, not copied.
import { buildChainsFor, transferablesOf } from './buildChainsFor.js';

self.onmessage = ({ data: { id, request } }) => {
  try {
    const result = buildChainsFor(request);
    self.postMessage({ id, result }, transferablesOf(result));
  } catch (error) {
    self.postMessage({ id, error: error instanceof Error ? error.message : String(error) });
  }
};
