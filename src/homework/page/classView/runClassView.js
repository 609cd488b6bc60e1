// Runs a class view (buildClassView.js) in a worker, so that unpacking a zip and grading hundreds of
// hand-ins never holds the page's thread; where a worker cannot start or fails (no Worker, a policy
// that refuses it), the same code runs on the page's thread, grading in slices of about 50 ms with
// a yield between them, and the page says so. Files' bytes are copied to the worker, not
// transferred, so that a worker that fails midway leaves them for the page to grade. The grading
// code is loaded on the page only then: the homework page a student opens does not carry it.
import ClassWorker from '../../class/classWorker.js?worker';

const ON_PAGE = 'graded on the page’s thread instead, in short slices';

/**
 * { run(request, onProgress) → Promise<view>, where(): 'a worker' | 'the page’s thread', problem(), dispose() }.
 * A run started while another is going supersedes it: the older one resolves null.
 */
export function createClassRunner({ useWorker = true } = {}) {
  let worker = null;
  let problem = '';
  let latest = 0;
  const pending = new Map(); // id → { resolve, reject, request, onProgress }

  const onPage = async (request, onProgress) => {
    const { buildClassView } = await import('../../class/buildClassView.js');
    return buildClassView(request, { onProgress, sliceMs: 50 });
  };

  function fallBack(reason) {
    problem = `The grading worker failed (${reason}): ${ON_PAGE}.`;
    worker?.terminate();
    worker = null;
    for (const [id, entry] of pending) {
      pending.delete(id);
      onPage(entry.request, entry.onProgress).then(entry.resolve, entry.reject);
    }
  }

  if (useWorker) {
    try {
      if (typeof Worker === 'undefined') throw new Error('this browser has no Web Workers');
      worker = new ClassWorker();
      worker.addEventListener('message', ({ data }) => {
        const entry = pending.get(data?.id);
        if (!entry) return;
        if (data.progress) { entry.onProgress?.(data.progress); return; }
        pending.delete(data.id);
        if (data.error !== undefined) entry.reject(new Error(data.error));
        else entry.resolve(data.id === latest ? data.view : null);
      });
      worker.addEventListener('error', (event) => { event.preventDefault?.(); fallBack(event.message || 'it could not load'); });
    } catch (error) {
      worker = null;
      problem = `The grading worker could not start (${error?.message || error}): ${ON_PAGE}.`;
    }
  }

  return {
    run(request, onProgress) {
      latest += 1;
      const id = latest;
      if (!worker) return onPage(request, onProgress).then((view) => (id === latest ? view : null));
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, request, onProgress });
        worker.postMessage({ id, request });
      });
    },
    where: () => (worker ? 'a worker' : 'the page’s thread'),
    problem: () => problem,
    dispose() {
      worker?.terminate();
      worker = null;
    },
  };
}
