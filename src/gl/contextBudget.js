// The page's budget of live WebGL contexts: browsers drop the oldest context past about 16, so the
// lab keeps at most 8. Kept apart from createRenderer.js (which imports three.js) so that pages and
// panels that only count contexts, or only ask whether WebGL2 exists, do not download three.js.

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

/** Counts a context that has just been created; returns the function that gives its place back. */
export function countContext() {
  contextStats.live += 1;
  contextStats.created += 1;
  contextStats.peak = Math.max(contextStats.peak, contextStats.live);
  let released = false;
  return () => {
    if (released) return;
    released = true;
    contextStats.live -= 1;
  };
}
