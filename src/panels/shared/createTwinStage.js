// The two-sphere stage of the fresnel-lighting and metals panels: one canvas drawn by one
// full-screen shader (the spheres are ray-cast in shaders/twinStage.glsl), a label
// over each half, and the map from a view angle θ to the pixel that shows it (for probes and tests).
import { createShaderView } from '../../gl/createShaderView.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { startWebGL } from './startWebGL.js';
import './twinStage.css';
import { el } from '../../ui/el.js';
import { DEG } from '../../optics/angles.js';
import { stackOnPhone } from './stackOnPhone.js';


/** Unit spheres seen from this far from their centres, with this vertical field of view, from a little above. */
export const STAGE_CAMERA = Object.freeze({ distance: 4, fovDeg: 36, elevationDeg: 10 });

/**
 * Horizontal offset from a half's centre, in half canvas heights, of the point on the sphere's
 * midline seen at view angle θ. In the eye–centre–surface triangle the sine rule gives
 * sin θ = distance · sin α, with α the ray's angle off the axis; the shader's ray is
 * focal·forward + offset·right with focal = 1/tan(fov/2), so offset = focal · tan α.
 */
export function offsetAtAngle(thetaDeg, { distance, fovDeg } = STAGE_CAMERA) {
  const alpha = Math.asin(Math.sin(thetaDeg * DEG) / distance);
  return Math.tan(alpha) / Math.tan((fovDeg * DEG) / 2);
}

/**
 * host: where the stage goes. fragment: GLSL source that includes <twinStage>
 * and <environment>. uniforms: its own uniforms. Returns null for `view` when WebGL2 is missing
 * (the stage then shows `fallback` in words). cache: createShaderView's option, for a fragment that
 * keeps its view terms.
 */
export function createTwinStage(host, { fragment, uniforms, ariaLabel, fallback, onFrame, cache = null }) {
  const stage = el('div', 'twin-stage');
  const canvas = el('canvas', 'twin-stage-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', ariaLabel);
  const labels = [el('span'), el('span')];
  const labelRow = el('div', 'twin-stage-labels');
  labelRow.append(...labels);
  stage.append(canvas, labelRow);
  host.append(stage);

  const { distance, fovDeg, elevationDeg } = STAGE_CAMERA;
  const view = startWebGL(stage, () => createShaderView(canvas, {
    fragment,
    onFrame,
    cache,
    maxPixels: 700_000, // two analytic spheres: sharp enough on a projector, cheap in SwiftShader
    uniforms: {
      ...uniforms,
      uCamera: { value: [distance, 1 / Math.tan((fovDeg * DEG) / 2), elevationDeg * DEG] },
      uSunDir: { value: [0, 1, 0] },
      uStacked: { value: 0 },
    },
  }), fallback);

  // On a phone the spheres stand one above the other, each as large as the screen is wide allows.
  const layout = stackOnPhone(stage, 'twin-stacked', view);

  /**
   * CSS pixel (within the canvas) of the point at view angle θ on sphere `side` (0 left, 1 right),
   * in the image direction `towardDeg` from the sphere's centre (0 right, 90 up, 180 left); every
   * direction works alike because the camera looks straight at the centre.
   */
  function pointAt(side, thetaDeg, towardDeg = 90) {
    const { width, height } = canvas.getBoundingClientRect();
    const stacked = layout.stacked();
    const r = offsetAtAngle(thetaDeg) * (stacked ? height / 4 : height / 2);
    const cx = stacked ? width / 2 : (side + 0.5) * (width / 2);
    const cy = stacked ? (side + 0.5) * (height / 2) : height / 2;
    return { x: cx + r * Math.cos(towardDeg * DEG), y: cy - r * Math.sin(towardDeg * DEG) };
  }

  return {
    canvas,
    view,
    pointAt,
    setLabels(texts) {
      texts.forEach((text, i) => { labels[i].textContent = text; });
    },
    setLight(azimuthDeg, elevationDeg) {
      if (view) view.uniforms.uSunDir.value = directionFromAngles(azimuthDeg, elevationDeg);
    },
    render: () => view?.render(),
    /** [r, g, b, a] bytes at view angle θ on a sphere (drawn now). */
    readAt(side, thetaDeg, towardDeg = 90) {
      const { x, y } = pointAt(side, thetaDeg, towardDeg);
      return view.readPixel(x, y);
    },
    dispose() {
      layout.dispose();
      view?.dispose();
    },
  };
}
