// Runs a class view (buildClassView.js) in a worker, so that unpacking a zip and grading hundreds of
// hand-ins never holds the page's thread; where a worker cannot start or fails (no Worker, a policy
// that refuses it), the same code runs on the page's thread, grading in slices of about 50 ms with
// a yield between them, and the page says so. Files' bytes are copied to the worker, not
// transferred, so that a worker that fails midway leaves them for the page to grade. The grading
// code is loaded on the page only then: the homework page a student opens does not carry it.
// The worker speaks the page's language: each request says which (currentLanguage), and the
// worker loads that catalogue before it reads a file (classWorker.js).
import ClassWorker from '../../class/classWorker.js?worker';
import english from 'virtual:messages/en/class';
import { currentLanguage, messages } from '../../../i18n/messages.js';

const t = messages('class', english);

/**
 * { run(request, onProgress) → Promise<view>, where(): 'worker' | 'page', problem(), dispose() }.
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
    problem = t('runner.failed', { reason });
    worker?.terminate();
    worker = null;
    for (const [id, entry] of pending) {
      pending.delete(id);
      onPage(entry.request, entry.onProgress).then(entry.resolve, entry.reject);
    }
  }

  if (useWorker) {
    try {
      if (typeof Worker === 'undefined') throw new Error(t('runner.noWorkers'));
      worker = new ClassWorker();
      worker.addEventListener('message', ({ data }) => {
        const entry = pending.get(data?.id);
        if (!entry) return;
        if (data.progress) { entry.onProgress?.(data.progress); return; }
        pending.delete(data.id);
        if (data.error !== undefined) entry.reject(new Error(data.error));
        else entry.resolve(data.id === latest ? data.view : null);
      });
      worker.addEventListener('error', (event) => { event.preventDefault?.(); fallBack(event.message || t('runner.notLoaded')); });
    } catch (error) {
      worker = null;
      problem = t('runner.noStart', { reason: error?.message || error });
    }
  }

  return {
    run(request, onProgress) {
      latest += 1;
      const id = latest;
      if (!worker) return onPage(request, onProgress).then((view) => (id === latest ? view : null));
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, request, onProgress });
        worker.postMessage({ id, request, lang: currentLanguage() });
      });
    },
    where: () => (worker ? 'worker' : 'page'),
    problem: () => problem,
    dispose() {
      worker?.terminate();
      worker = null;
    },
  };
}
