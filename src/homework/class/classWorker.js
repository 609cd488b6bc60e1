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

/**
 * Answers class-view requests on a worker's global scope (or anything with addEventListener and
 * postMessage, as tests give it).
 * @param {{ addEventListener: (type: 'message', listener: (event: { data: any }) => void) => void,
 *   postMessage: (message: any) => void }} scope
 */
export function serveClassView(scope) {
  scope.addEventListener('message', async (event) => {
    const { id, request, lang } = event.data ?? {};
    try {
      if (lang !== undefined) useWorkerLanguage(lang);
      // Nothing else runs on a worker's thread, so grading does not pause between slices.
      const view = await buildClassView(request, {
        pause: () => Promise.resolve(), sliceMs: 250, onProgress: (progress) => scope.postMessage({ id, progress }),
      });
      scope.postMessage({ id, view });
    } catch (error) {
      scope.postMessage({ id, error: error?.message ?? String(error) });
    }
  });
}

const global = /** @type {any} */ (globalThis);
if (typeof global.WorkerGlobalScope === 'function' && global instanceof global.WorkerGlobalScope) serveClassView(global);
