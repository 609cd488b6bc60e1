// @ts-check
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
import { own } from '../../../host/own.js';

const t = messages('class', english);

/** @typedef {import('../../class/buildClassView.js').ClassView} ClassView */
/** @typedef {import('../../class/buildClassView.js').ViewProgress} ViewProgress */
/** @typedef {Parameters<typeof import('../../class/buildClassView.js').buildClassView>[0]} Request */
/** @typedef {((progress: ViewProgress) => void) | undefined} OnProgress */
/**
 * @typedef {{ resolve: (view: ClassView | null) => void, reject: (error: Error) => void, request: Request,
 *   onProgress: OnProgress }} Pending
 */

/**
 * { run(request, onProgress) → Promise<view>, where(): 'worker' | 'page', problem(), dispose() }.
 * A run started while another is going supersedes it: the older one resolves null.
 * @param {{ useWorker?: boolean }} [options]
 */
export function createClassRunner({ useWorker = true } = {}) {
  /** @type {Worker | null} */
  let worker = null;
  let problem = '';
  let latest = 0;
  /** @type {Map<number, Pending>} */
  const pending = new Map();

  /** @type {(request: Request, onProgress: OnProgress) => Promise<ClassView>} */
  const onPage = async (request, onProgress) => {
    const { buildClassView } = await import('../../class/buildClassView.js');
    return buildClassView(request, { onProgress, sliceMs: 50 });
  };

  /** @param {string} reason */
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
      worker.addEventListener('message', (event) => {
        // The worker's replies (classWorker.js): { id, progress }, then { id, view } or { id, error }.
        /** @type {unknown} */
        const data = event.data;
        const field = (/** @type {string} */ key) => own(data, key);
        const id = field('id');
        const entry = typeof id === 'number' ? pending.get(id) : undefined;
        if (typeof id !== 'number' || !entry) return;
        const progress = field('progress');
        if (progress) { entry.onProgress?.(/** @type {ViewProgress} */ (progress)); return; } // the worker's own progress report
        pending.delete(id);
        const error = field('error');
        if (error !== undefined) entry.reject(new Error(String(error)));
        else entry.resolve(id === latest ? /** @type {ClassView} */ (field('view')) : null); // buildClassView's result, cloned
      });
      worker.addEventListener('error', (event) => { event.preventDefault?.(); fallBack(event.message || t('runner.notLoaded')); });
    } catch (error) {
      worker = null;
      problem = t('runner.noStart', { reason: error instanceof Error ? error.message || error : error });
    }
  }

  return {
    /**
     * @param {Request} request
     * @param {OnProgress} [onProgress]
     * @returns {Promise<ClassView | null>}
     */
    run(request, onProgress) {
      latest += 1;
      const id = latest;
      const running = worker;
      if (!running) return onPage(request, onProgress).then((view) => (id === latest ? view : null));
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, request, onProgress });
        running.postMessage({ id, request, lang: currentLanguage() });
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
