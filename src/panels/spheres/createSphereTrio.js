// Three spheres from one camera in one WebGL context: exact Fresnel, Schlick, and the error
// heatmap, ray-cast in one full-screen pass (spheres.frag.glsl) with the camera of trioCamera.js.
// The sphere is exact, so no mesh is drawn: a software rasterizer or a weak integrated GPU pays
// once per pixel, not per triangle, and the hover readout uses the very same ray.
import { createShaderView } from '../../gl/createShaderView.js';
import { hexToLinear } from '../../ui/srgb.js';
import fragment from './spheres.frag.glsl?raw';
import { hitSphere, rayThrough, sphereSquares, trioCamera, VIEW_COUNT } from './trioCamera.js';

export const SPHERE_MODES = ['exact', 'schlick', 'error'];

export function createSphereTrio(canvas, { onChange, onFrame } = {}) {
  const uniforms = {
    uEye: { value: [0, 0, 6] }, uForward: { value: [0, 0, -1] }, uRight: { value: [1, 0, 0] }, uUp: { value: [0, 1, 0] },
    uTanHalfFov: { value: 0.25 },
    uNI: { value: 1 }, uNT: { value: 1.5 },
    uKd: { value: [0, 0, 0] }, uKs: { value: [1, 1, 1] },
    uSunDir: { value: [0, 1, 0] }, uEnvStrength: { value: 1 }, uErrScale: { value: 0.05 },
    uSingle: { value: -1 },
  };
  const view = { azimuth: 0, elevation: 15, distance: 6 };
  let camera = trioCamera(view);
  // The sky depends on the camera, the sun and the environment's strength only: it is kept, and a
  // change of the optics or the colours redraws the squares round the spheres alone.
  const backdrop = {
    live: ['uNI', 'uNT', 'uKd', 'uKs', 'uErrScale'],
    regions: (width, height) => sphereSquares(
      { distance: view.distance, tanHalfFov: camera.tanHalfFov }, width, height, uniforms.uSingle.value < 0 ? VIEW_COUNT : 1,
    ),
  };
  const shaderView = createShaderView(canvas, { fragment, uniforms, onFrame, maxPixels: 1_500_000, backdrop });

  function placeCamera() {
    camera = trioCamera(view);
    uniforms.uEye.value = camera.eye;
    uniforms.uForward.value = camera.forward;
    uniforms.uRight.value = camera.right;
    uniforms.uUp.value = camera.up;
    uniforms.uTanHalfFov.value = camera.tanHalfFov;
  }
  placeCamera();

  // Orbit by a drag of the mouse or one finger and by arrow keys (the canvas is focusable); the
  // wheel or two fingers pinching zoom.
  let drag = null;
  let pinch = null;
  const pointers = new Map(); // pointerId → { x, y }
  const span = () => {
    const [a, b] = [...pointers.values()];
    return Math.max(1, Math.hypot(a.x - b.x, a.y - b.y));
  };
  const onPointerDown = (event) => {
    pointers.set(event.pointerId, { x: event.clientX, y: event.clientY });
    canvas.setPointerCapture(event.pointerId);
    if (pointers.size === 2) {
      drag = null; // a second finger: a pinch, not an orbit
      pinch = { span: span(), distance: view.distance };
    } else if (pointers.size === 1) {
      drag = { x: event.clientX, y: event.clientY, azimuth: view.azimuth, elevation: view.elevation };
    }
  };
  const onPointerMove = (event) => {
    if (pointers.has(event.pointerId)) pointers.set(event.pointerId, { x: event.clientX, y: event.clientY });
    if (pinch && pointers.size >= 2) {
      setView({ distance: (pinch.distance * pinch.span) / span() }); // fingers apart: nearer
      return;
    }
    if (!drag) return;
    const scale = 180 / Math.max(200, canvas.getBoundingClientRect().height);
    setView({
      azimuth: drag.azimuth - (event.clientX - drag.x) * scale,
      elevation: drag.elevation + (event.clientY - drag.y) * scale,
    });
  };
  const onPointerUp = (event) => {
    pointers.delete(event.pointerId);
    if (pointers.size < 2) pinch = null;
    drag = null; // the finger left after a pinch does not start an orbit
  };
  // The wheel zooms once the reader has picked the view (clicked or tabbed to it) or holds Ctrl:
  // a page or a notebook scrolled past the canvas keeps scrolling.
  const onWheel = (event) => {
    if (document.activeElement !== canvas && !event.ctrlKey) return;
    event.preventDefault();
    setView({ distance: view.distance * Math.exp(event.deltaY * 0.001) });
  };
  const onKeyDown = (event) => {
    const step = event.shiftKey ? 15 : 5;
    const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] };
    const move = moves[event.key];
    if (!move) return;
    event.preventDefault();
    event.stopPropagation(); // arrows on a focused canvas orbit; elsewhere they belong to the page
    setView({ azimuth: view.azimuth + move[0], elevation: view.elevation + move[1] });
  };
  canvas.addEventListener('pointerdown', onPointerDown);
  canvas.addEventListener('pointermove', onPointerMove);
  canvas.addEventListener('pointerup', onPointerUp);
  canvas.addEventListener('pointercancel', onPointerUp);
  canvas.addEventListener('wheel', onWheel, { passive: false });
  canvas.addEventListener('keydown', onKeyDown);

  function setView(next, { silent = false } = {}) {
    const azimuth = next.azimuth ?? view.azimuth;
    view.azimuth = ((((azimuth + 180) % 360) + 360) % 360) - 180;
    view.elevation = Math.min(85, Math.max(-85, next.elevation ?? view.elevation));
    view.distance = Math.min(10, Math.max(2.2, next.distance ?? view.distance));
    placeCamera();
    shaderView.render();
    if (!silent) onChange?.({ ...view });
  }

  return {
    shaderView,
    frames: shaderView.frames,
    get view() { return { ...view }; },
    setView,
    /** Updates the optics and look; colours as the controls give them ('#rrggbb', sRGB). */
    setParams({ nI, nT, kd, ks, sunDir, envStrength, errScale }) {
      uniforms.uNI.value = nI;
      uniforms.uNT.value = nT;
      uniforms.uKd.value = hexToLinear(kd);
      uniforms.uKs.value = hexToLinear(ks);
      uniforms.uSunDir.value = sunDir;
      uniforms.uEnvStrength.value = envStrength;
      uniforms.uErrScale.value = errScale;
      shaderView.render();
    },
    /** One sphere alone ('exact', 'schlick' or 'error'; a narrow screen), or all three (null). */
    setSingle(mode) {
      const next = mode === null ? -1 : SPHERE_MODES.indexOf(mode);
      if (next === uniforms.uSingle.value) return;
      uniforms.uSingle.value = next;
      shaderView.render();
    },
    get single() { return uniforms.uSingle.value < 0 ? null : SPHERE_MODES[uniforms.uSingle.value]; },
    /** Which sphere is under a client point, and the cos θ between its normal and the view there. */
    pick(clientX, clientY) {
      const rect = canvas.getBoundingClientRect();
      const alone = uniforms.uSingle.value >= 0;
      const count = alone ? 1 : VIEW_COUNT;
      const w = rect.width / count;
      const slot = Math.floor((clientX - rect.left) / w);
      if (slot < 0 || slot >= count) return null;
      const x = ((clientX - rect.left - slot * w) / w) * 2 - 1;
      const y = 1 - ((clientY - rect.top) / rect.height) * 2;
      const hit = hitSphere(camera.eye, rayThrough(camera, x, y, w / rect.height));
      return hit && { mode: SPHERE_MODES[alone ? uniforms.uSingle.value : slot], cosTheta: hit.cosTheta };
    },
    /** Draws now and reads one pixel (CSS coordinates within the canvas) as [r, g, b, a] bytes. */
    readPixel: (x, y) => shaderView.readPixel(x, y),
    /** Draws now and returns the canvas as a PNG data URL (the drawing buffer is not preserved). */
    toDataURL: () => shaderView.toDataURL(),
    dispose() {
      canvas.removeEventListener('pointerdown', onPointerDown);
      canvas.removeEventListener('pointermove', onPointerMove);
      canvas.removeEventListener('pointerup', onPointerUp);
      canvas.removeEventListener('pointercancel', onPointerUp);
      canvas.removeEventListener('wheel', onWheel);
      canvas.removeEventListener('keydown', onKeyDown);
      shaderView.dispose();
    },
  };
}
