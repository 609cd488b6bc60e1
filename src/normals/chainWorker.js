// Dedicated worker: builds a share of the normal-mips chains off the page's thread, so that a
// 512² or 1024² map (several hundred ms of work) never blocks input. Each message { id, request }
// is answered { id, result } or { id, error }; the typed arrays are transferred, not copied, and
// the pyramid only by the worker asked for it (request.withPyramid).
import { buildChainsFor, transferablesOf } from './buildChainsFor.js';

self.onmessage = ({ data: { id, request } }) => {
  try {
    const { pyramid, ...rest } = buildChainsFor(request);
    const result = request.withPyramid ? { pyramid, ...rest } : rest;
    self.postMessage({ id, result }, transferablesOf(result));
  } catch (error) {
    self.postMessage({ id, error: error instanceof Error ? error.message : String(error) });
  }
};
