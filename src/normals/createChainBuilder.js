// Builds the normal-mips chains in workers (chainWorker.js), each on a share of the techniques
// (splitTechniques: one per core, up to three; the page's thread only waits), and hands back only the newest request's
// result: a slider dragged through ten sizes costs the builds it started, but the panel applies
// the last one only. Without Worker support (or if a worker fails to start) the same pure code
// runs on the calling thread, so the panel works everywhere. Why that happened is given as a reason
// id and a detail (the browser's own message); the panel says it in words (chainProblemText).
import { buildChainsFor, mergeBuilds, splitTechniques } from './buildChainsFor.js';
import ChainWorker from './chainWorker.js?worker';

/** { workers, problem: null } or { workers: null, problem: { reason, detail } }. */
function startWorkers(count) {
  if (typeof Worker === 'undefined') return { workers: null, problem: { reason: 'noWorkers' } };
  const started = [];
  try {
    for (let i = 0; i < count; i += 1) started.push(new ChainWorker());
    return { workers: started, problem: null };
  } catch (error) {
    started.forEach((w) => w.terminate());
    return { workers: null, problem: { reason: 'workersNotStarted', detail: String(error?.message || error) } };
  }
}

/** Workers to use: one per core (the page's thread is idle meanwhile), at least 1, at most 3. */
export function workerCount(cores = globalThis.navigator?.hardwareConcurrency ?? 2) {
  return Math.min(3, Math.max(1, Math.floor(cores) || 1));
}

/**
 * createChainBuilder({ useWorker = true, workers = workerCount() }) → { build(request) →
 * Promise<{ pyramid, chains, uploads, ms, where, workers } | null>, where, workers, problem, dispose() }.
 * A build resolves null when a newer build was requested before it finished (the caller drops it);
 * it rejects on a bad request. workers: how many built it (0: the page's thread); where: the same
 * for the benchmark's log, 'N workers', '1 worker' or 'main thread'; ms: the slowest share's time.
 * problem: null, or why the builds run on the page's thread although workers were asked for:
 * { reason: 'noWorkers' | 'workersNotStarted' | 'workerFailed' | 'workerNotLoaded', detail? }.
 */
export function createChainBuilder({ useWorker = true, workers: count = workerCount() } = {}) {
  const shares = splitTechniques(count);
  let { workers, problem } = useWorker ? startWorkers(shares.length) : { workers: null, problem: null };
  let latest = 0;
  const pending = new Map(); // id → { resolve, reject, request, parts, left }

  const describe = () => (workers ? `${workers.length} worker${workers.length > 1 ? 's' : ''}` : 'main thread');

  function buildHere(id, request) {
    if (id !== latest) return null; // superseded: not worth building
    return { ...buildChainsFor(request), where: 'main thread', workers: 0 };
  }

  // A worker that cannot load (a blocked module, a bundling fault) makes all fall back for good.
  function fallBack(event) {
    problem = event?.message ? { reason: 'workerFailed', detail: String(event.message) } : { reason: 'workerNotLoaded' };
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
    entry.resolve(id === latest ? { ...mergeBuilds(entry.parts), where: describe(), workers: workers.length } : null);
  }

  workers?.forEach((worker, share) => {
    worker.onmessage = (event) => onMessage(share, event);
    worker.onerror = (event) => { event.preventDefault?.(); fallBack(event); };
  });

  return {
    get where() { return describe(); },
    /** How many workers build the chains (0: the page's thread). */
    get workers() { return workers ? workers.length : 0; },
    /** Why the builds run on the page's thread although workers were asked for (null when they do not). */
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
