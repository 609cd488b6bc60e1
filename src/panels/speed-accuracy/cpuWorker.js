// Dedicated worker for the CPU timing of the Fresnel methods (timeMethodsCpu): here only the
// float64 context ever runs, so the JIT sees each method with one arithmetic context, as a
// program that computes in float64 would; on the page the same code has also run the float32 and
// float16 emulations for the error figures, which makes its calls polymorphic and several times
// slower. Messages: { config } in; { progress: [done, total] } and then { result } or { error } out.
import { timeMethodsCpu } from '../../methods/timeMethodsCpu.js';

self.onmessage = async ({ data: { config } }) => {
  try {
    const result = await timeMethodsCpu({ ...config, onProgress: (done, total) => self.postMessage({ progress: [done, total] }) });
    self.postMessage({ result });
  } catch (error) {
    self.postMessage({ error: error instanceof Error ? error.message : String(error) });
  }
};
