// Builds the normal-mips chains in workers (chainWorker.js), each on a share of the techniques
// (splitTechniques: one per core, up to three; the page's thread only waits), and hands back only the newest request's
// result: a slider dragged through ten sizes costs the builds it started, but the panel applies
// the last one only. Without Worker support (or if a worker fails to start) the same pure code
// runs on the calling thread, so the panel works everywhere.
import { buildChainsFor, mergeBuilds, splitTechniques } from './buildChainsFor.js';
import ChainWorker from './chainWorker.js?worker';

const ON_PAGE = 'the chains are built on the page’s thread instead, which may pause the page while they build';

/** { workers } or { workers: null, problem } in words. */
function startWorkers(count) {
  if (typeof Worker === 'undefined') return { workers: null, problem: `This browser has no Web Workers: ${ON_PAGE}.` };
  const started = [];
  try {
    for (let i = 0; i < count; i += 1) started.push(new ChainWorker());
    return { workers: started, problem: '' };
  } catch (error) {
    started.forEach((w) => w.terminate());
    return { workers: null, problem: `The chain-building workers could not start (${error?.message || error}): ${ON_PAGE}.` };
  }
}

/** Workers to use: one per core (the page's thread is idle meanwhile), at least 1, at most 3. */
export function workerCount(cores = globalThis.navigator?.hardwareConcurrency ?? 2) {
  return Math.min(3, Math.max(1, Math.floor(cores) || 1));
}

/**
 * createChainBuilder({ useWorker = true, workers = workerCount() }) → { build(request) →
 * Promise<{ pyramid, chains, uploads, ms, where } | null>, where, problem, dispose() }. A build resolves
 * null when a newer build was requested before it finished (the caller drops it); it rejects on
 * a bad request. where: 'N workers', '1 worker' or 'main thread'; ms: the slowest share's time.
 */
export function createChainBuilder({ useWorker = true, workers: count = workerCount() } = {}) {
  const shares = splitTechniques(count);
  let { workers, problem } = useWorker ? startWorkers(shares.length) : { workers: null, problem: '' };
  let latest = 0;
  const pending = new Map(); // id → { resolve, reject, request, parts, left }

  const describe = () => (workers ? `${workers.length} worker${workers.length > 1 ? 's' : ''}` : 'main thread');

  function buildHere(id, request) {
    if (id !== latest) return null; // superseded: not worth building
    return { ...buildChainsFor(request), where: 'main thread' };
  }

  // A worker that cannot load (a blocked module, a bundling fault) makes all fall back for good.
  function fallBack(event) {
    problem = `A chain-building worker failed (${event?.message || 'it could not load'}): ${ON_PAGE}.`;
    workers?.forEach((w) => w.terminate());
    workers = null;
    for (const [id, { resolve, reject, request }] of pending) {
      try { resolve(buildHere(id, request)); } catch (error) { reject(error); }
    }
    pending.clear();
  }

  function onMessage(share, { data: { id, result, error } }) {
    const entry = pending.get(id);
    if (!entry) return;
    if (error) {
      pending.delete(id);
      entry.reject(new RangeError(error));
      return;
    }
    entry.parts[share] = result;
    entry.left -= 1;
    if (entry.left > 0) return;
    pending.delete(id);
    entry.resolve(id === latest ? { ...mergeBuilds(entry.parts), where: describe() } : null);
  }

  workers?.forEach((worker, share) => {
    worker.onmessage = (event) => onMessage(share, event);
    worker.onerror = (event) => { event.preventDefault?.(); fallBack(event); };
  });

  return {
    get where() { return describe(); },
    /** Why the builds run on the page's thread although workers were asked for, in words ('' when they do not). */
    get problem() { return problem; },
    build(request) {
      latest += 1;
      const id = latest;
      if (!workers) {
        // Still asynchronous, so callers see one behaviour; a microtask keeps the order of requests.
        return Promise.resolve().then(() => buildHere(id, request));
      }
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, request, parts: [], left: workers.length });
        workers.forEach((worker, share) => {
          worker.postMessage({ id, request: { ...request, techniques: shares[share], withPyramid: share === 0 } });
        });
      });
    },
    dispose() {
      workers?.forEach((w) => w.terminate());
      workers = null;
      for (const { resolve } of pending.values()) resolve(null);
      pending.clear();
    },
  };
}
