// A WebGL2 context on a canvas, counted against the page's budget of live contexts
// (contextBudget.js). No depth, stencil or MSAA unless asked: the lab's passes are full-screen
// triangles that anti-alias themselves, and read-back contexts draw into float targets.
import { countContext } from './contextBudget.js';
import { WebGL2Unavailable } from './webgl2Unavailable.js';
import { currentOwner } from './faultOwner.js';
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

/**
 * @param {HTMLCanvasElement} canvas
 * @param {WebGLContextAttributes} [attributes]
 * @returns {{ gl: WebGL2RenderingContext, dispose: () => void }} dispose() gives the context back now (not at GC)
 *   and its place in the budget.
 */
export function createContext(canvas, attributes = {}) {
  // No probe on a canvas of its own first (hasWebGL2): making a context costs a software GPU a
  // good part of a second, and the context itself answers the question.
  if (typeof WebGL2RenderingContext === 'undefined') throw new WebGL2Unavailable(t('noWebgl2'));
  const gl = canvas.getContext('webgl2', {
    alpha: false, antialias: false, depth: false, stencil: false, powerPreference: 'high-performance', ...attributes,
  });
  if (!gl) throw new WebGL2Unavailable(t('webgl2NotOnCanvas'));
  const release = countContext();
  // The panel that made the context says so while it is gone (panelFaults.js). Asking for the
  // restore (preventDefault) is what makes the browser give it back; the users rebuild on restore.
  const owner = currentOwner();
  const onLost = (event) => {
    event.preventDefault();
    owner?.contextLost();
  };
  const onRestored = () => owner?.contextRestored();
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);
  let disposed = false;
  return {
    gl,
    dispose() {
      if (disposed) return;
      disposed = true;
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      gl.getExtension('WEBGL_lose_context')?.loseContext();
      release();
    },
  };
}
