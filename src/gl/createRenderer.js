// A three.js WebGLRenderer on a canvas, counted against the page's budget of live contexts
// (contextBudget.js). Only the benchmark's peer (the ordinary three.js way of drawing the hero's
// spheres) uses three.js; the panels draw with createContext / createShaderView.
import { WebGLRenderer } from 'three';
import { countContext, hasWebGL2 } from './contextBudget.js';
import { WebGL2Unavailable } from './webgl2Unavailable.js';
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

/** A WebGLRenderer whose dispose() also releases the context and its place in the budget. */
export function createRenderer(canvas, options = {}) {
  if (!hasWebGL2()) throw new WebGL2Unavailable(t('noWebgl2'));
  let renderer;
  try {
    renderer = new WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance', ...options });
  } catch (error) {
    throw new WebGL2Unavailable(t('webgl2NotStarted', { reason: error.message }));
  }
  renderer.autoClear = false;
  const release = countContext();
  const dispose = renderer.dispose.bind(renderer);
  let disposed = false;
  renderer.dispose = () => {
    if (disposed) return;
    disposed = true;
    dispose();
    renderer.forceContextLoss();
    release();
  };
  return renderer;
}
