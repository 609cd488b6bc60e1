// Builds the normal-mips chains in a worker (chainWorker.js) and hands back only the newest
// request's result: a slider dragged through ten sizes costs the builds it started, but the
// panel applies the last one only. Without Worker support (or if the worker fails to start) the
// same pure code runs on the calling thread, so the panel works everywhere.
import { buildChainsFor } from './buildChainsFor.js';

function startWorker() {
  if (typeof Worker === 'undefined') return null;
  try {
    return new Worker(new URL('./chainWorker.js', import.meta.url), { type: 'module' });
  } catch {
    return null;
  }
}

/**
 * createChainBuilder() → { build(request) → Promise<{ pyramid, chains, ms, where } | null>,
 * where, dispose() }. A build resolves null when a newer build was requested before it finished
 * (the caller drops it); it rejects on a bad request. where: 'worker' or 'main thread'.
 */
export function createChainBuilder({ useWorker = true } = {}) {
  let worker = useWorker ? startWorker() : null;
  let latest = 0;
  const pending = new Map(); // id → { resolve, reject, request }

  function buildHere(id, request) {
    if (id !== latest) return null; // superseded: not worth building
    return { ...buildChainsFor(request), where: 'main thread' };
  }

  // A worker that cannot load (a blocked module, a bundling fault) falls back for good.
  function fallBack() {
    worker?.terminate();
    worker = null;
    for (const [id, { resolve, reject, request }] of pending) {
      try { resolve(buildHere(id, request)); } catch (error) { reject(error); }
    }
    pending.clear();
  }

  if (worker) {
    worker.onmessage = ({ data: { id, result, error } }) => {
      const entry = pending.get(id);
      if (!entry) return;
      pending.delete(id);
      if (error) entry.reject(new RangeError(error));
      else entry.resolve(id === latest ? { ...result, where: 'worker' } : null);
    };
    worker.onerror = (event) => { event.preventDefault?.(); fallBack(); };
  }

  return {
    get where() { return worker ? 'worker' : 'main thread'; },
    build(request) {
      latest += 1;
      const id = latest;
      if (!worker) {
        // Still asynchronous, so callers see one behaviour; a microtask keeps the order of requests.
        return Promise.resolve().then(() => buildHere(id, request));
      }
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, request });
        worker.postMessage({ id, request });
      });
    },
    dispose() {
      worker?.terminate();
      worker = null;
      for (const { resolve } of pending.values()) resolve(null);
      pending.clear();
    },
  };
}
