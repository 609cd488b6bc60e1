// One WebGL2 renderer on a canvas, counted against the page's budget of live contexts
// (browsers drop the oldest context past about 16; the lab keeps at most 8), with a capped pixel
// count so a 4K projector or a retina laptop stays fast.
import { WebGLRenderer } from 'three';

export class WebGL2Unavailable extends Error {}

export const MAX_LIVE_CONTEXTS = 8;
export const contextStats = { live: 0, peak: 0, created: 0 };

/** True when the browser can create a WebGL2 context at all (probed once). */
let webgl2Probe = null;
export function hasWebGL2() {
  if (webgl2Probe === null) {
    try {
      const gl = document.createElement('canvas').getContext('webgl2');
      webgl2Probe = Boolean(gl);
      gl?.getExtension('WEBGL_lose_context')?.loseContext(); // the probe must not hold a context
    } catch {
      webgl2Probe = false;
    }
  }
  return webgl2Probe;
}

/** Device pixel ratio capped at maxRatio and so that the drawing buffer holds at most maxPixels. */
export function cappedPixelRatio(cssWidth, cssHeight, deviceRatio, maxRatio = 2, maxPixels = 3_000_000) {
  const area = Math.max(1, cssWidth * cssHeight);
  return Math.max(0.5, Math.min(deviceRatio || 1, maxRatio, Math.sqrt(maxPixels / area)));
}

/** A WebGLRenderer whose dispose() also releases the context and its place in the budget. */
export function createRenderer(canvas, options = {}) {
  if (!hasWebGL2()) throw new WebGL2Unavailable('This browser has no WebGL2.');
  let renderer;
  try {
    renderer = new WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance', ...options });
  } catch (error) {
    throw new WebGL2Unavailable(`WebGL2 could not start: ${error.message}`);
  }
  renderer.autoClear = false;
  contextStats.live += 1;
  contextStats.created += 1;
  contextStats.peak = Math.max(contextStats.peak, contextStats.live);
  const dispose = renderer.dispose.bind(renderer);
  let disposed = false;
  renderer.dispose = () => {
    if (disposed) return;
    disposed = true;
    dispose();
    renderer.forceContextLoss();
    contextStats.live -= 1;
  };
  return renderer;
}
