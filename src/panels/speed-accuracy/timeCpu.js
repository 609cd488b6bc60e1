// CPU timing for the benchmark, in a worker of its own (cpuWorker.js) where only the
// float64 arithmetic runs; where workers are unavailable, on the page as before. Resolves to
// timeMethodsCpu's result plus `where` ('worker' or 'page').
import { timeMethodsCpu } from '../../methods/timeMethodsCpu.js';
import CpuWorker from './cpuWorker.js?worker';

export function timeCpu({ signal, onProgress, ...config }) {
  let worker = null;
  try {
    worker = typeof Worker === 'undefined' ? null
      : new CpuWorker();
  } catch {
    worker = null;
  }
  const onPage = () => timeMethodsCpu({ ...config, signal, onProgress }).then((r) => ({ ...r, where: 'page' }));
  if (!worker) return onPage();
  return new Promise((resolve, reject) => {
    const stop = () => { worker.terminate(); signal?.removeEventListener('abort', abort); };
    const abort = () => { stop(); reject(signal.reason); };
    signal?.throwIfAborted();
    signal?.addEventListener('abort', abort, { once: true });
    worker.onmessage = ({ data }) => {
      if (data.progress) { onProgress?.(...data.progress); return; }
      stop();
      if (data.error) reject(new Error(data.error));
      else resolve({ ...data.result, where: 'worker' });
    };
    worker.onerror = (event) => { event.preventDefault?.(); stop(); onPage().then(resolve, reject); };
    worker.postMessage({ config });
  });
}
