// The first WebGL context of a page also opens the page's channel to the GPU process, and the
// thread that asks waits for it: 70–340 ms on this machine's software GPU, against 15–45 ms for
// any context after it (measured in Chromium 150). A worker that makes a context first opens the
// channel off the page's thread, so the first panel's context costs what the later ones do. Where
// workers or OffscreenCanvas are missing (or a page's CSP refuses the worker) nothing is lost but
// the head start.
import GpuWarmWorker from './gpuWarmWorker.js?worker';

let warming = null;

/** Resolves once the GPU channel is open (or could not be opened by a worker), at most after `ms`. */
export function warmGpu(ms = 1000) {
  warming ??= new Promise((resolve) => {
    if (typeof Worker === 'undefined' || typeof OffscreenCanvas === 'undefined') {
      resolve(false);
      return;
    }
    const timer = setTimeout(() => resolve(false), ms);
    const done = (ok) => {
      clearTimeout(timer);
      resolve(ok);
    };
    try {
      const worker = new GpuWarmWorker();
      worker.onmessage = (event) => done(event.data === true);
      worker.onerror = () => done(false);
    } catch {
      done(false);
    }
  });
  return warming;
}
