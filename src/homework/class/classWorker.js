// @ts-check
// The class view's worker: reading a zip, grading hundreds of hand-ins and summarising them run
// here, so the page's thread stays free whatever the class brings. The page starts it with
//   new Worker(new URL('./class/classWorker.js', import.meta.url), { type: 'module' })
// (or `import ClassWorker from './class/classWorker.js?worker'`, which the single-file pages inline),
// posts { id, request, lang? } (buildClassView's request; files' bytes may be transferred; lang: the
// page's language, which every word of the view is written in) and gets { id, progress } messages,
// then { id, view } or { id, error }. Everything posted back is plain data (structured-cloneable).
import { buildClassView } from './buildClassView.js';
import { useWorkerLanguage } from './classWorkerLanguage.js';
import { own } from '../../host/own.js';

/**
 * Answers class-view requests on a worker's global scope (or anything with addEventListener and
 * postMessage, as tests give it).
 * @param {{ addEventListener(type: 'message', listener: (event: { data: unknown }) => void): void,
 *   postMessage(message: unknown): void }} scope
 */
export function serveClassView(scope) {
  scope.addEventListener('message', async (event) => {
    const message = event.data;
    /** @type {(key: string) => unknown} the message's field (the page posts { id, request, lang }) */
    const field = (key) => own(message, key);
    const id = field('id');
    const request = field('request');
    const lang = field('lang');
    try {
      if (lang !== undefined) useWorkerLanguage(lang);
      // Nothing else runs on a worker's thread, so grading does not pause between slices.
      const view = await buildClassView(typeof request === 'object' ? request : null, {
        pause: () => Promise.resolve(), sliceMs: 250, onProgress: (progress) => scope.postMessage({ id, progress }),
      });
      scope.postMessage({ id, view });
    } catch (error) {
      scope.postMessage({ id, error: error instanceof Error ? error.message : String(error) });
    }
  });
}

// WorkerGlobalScope is not in the DOM library's types (the page's); in a worker, globalThis is one.
const { WorkerGlobalScope } = /** @type {typeof globalThis & { WorkerGlobalScope?: unknown }} */ (globalThis);
if (typeof WorkerGlobalScope === 'function' && globalThis instanceof WorkerGlobalScope) {
  serveClassView(globalThis);
}
