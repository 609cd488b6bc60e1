// One WebGL2 renderer on a canvas, with a capped pixel count so a 4K projector or a retina
// laptop stays fast: the cap trades a little sharpness for a steady frame time.
import { WebGLRenderer } from 'three';

export class WebGL2Unavailable extends Error {}

/** True when the browser can create a WebGL2 context at all. */
export function hasWebGL2() {
  try {
    return Boolean(document.createElement('canvas').getContext('webgl2'));
  } catch {
    return false;
  }
}

/** Device pixel ratio capped at maxRatio and so that the drawing buffer holds at most maxPixels. */
export function cappedPixelRatio(cssWidth, cssHeight, deviceRatio, maxRatio = 2, maxPixels = 3_000_000) {
  const area = Math.max(1, cssWidth * cssHeight);
  return Math.max(0.5, Math.min(deviceRatio || 1, maxRatio, Math.sqrt(maxPixels / area)));
}

export function createRenderer(canvas) {
  if (!hasWebGL2()) throw new WebGL2Unavailable('This browser has no WebGL2.');
  let renderer;
  try {
    renderer = new WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  } catch (error) {
    throw new WebGL2Unavailable(`WebGL2 could not start: ${error.message}`);
  }
  renderer.autoClear = false;
  return renderer;
}
