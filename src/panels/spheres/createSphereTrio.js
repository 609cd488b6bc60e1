// Three spheres from one camera in one WebGL context: exact Fresnel, Schlick, and the error
// heatmap. One sphere mesh drawn into three viewports with a mode uniform; the sky is a
// back-facing dome with the same procedural environment the spheres reflect.
import {
  BackSide, Color, GLSL3, Mesh, PerspectiveCamera, RawShaderMaterial, Raycaster, Scene, Sphere,
  SphereGeometry, Vector2, Vector3,
} from 'three';
import { assembleShader } from '../../gl/shaderChunks.js';
import sphereVertex from './spheres.vert.glsl?raw';
import sphereFragment from './spheres.frag.glsl?raw';
import skyFragment from './sky.frag.glsl?raw';
import { cappedPixelRatio, createRenderer } from '../../gl/createRenderer.js';
import { onDemand } from '../../gl/onDemand.js';
import { readPixel } from '../../gl/readPixel.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';

export const SPHERE_MODES = ['exact', 'schlick', 'error'];
/** The sky dome's shaders (the benchmark draws the same sky behind its peer). */
export const SKY_SHADERS = Object.freeze({ vertex: assembleShader(sphereVertex), fragment: assembleShader(skyFragment) });


export function createSphereTrio(canvas, { onChange, onFrame } = {}) {
  const renderer = createRenderer(canvas);
  renderer.setScissorTest(true);
  const camera = new PerspectiveCamera(28, 1, 0.1, 100);
  const shared = { uSunDir: { value: new Vector3(0, 1, 0) }, uEnvStrength: { value: 1 } };
  const uniforms = {
    ...shared,
    uMode: { value: 0 },
    uNI: { value: 1 },
    uNT: { value: 1.5 },
    uKd: { value: new Color() },
    uKs: { value: new Color() },
    uErrScale: { value: 0.05 },
  };
  const vertexShader = SKY_SHADERS.vertex;
  const sphereMaterial = new RawShaderMaterial({
    glslVersion: GLSL3, vertexShader, fragmentShader: assembleShader(sphereFragment), uniforms,
  });
  const skyMaterial = new RawShaderMaterial({
    glslVersion: GLSL3, vertexShader, fragmentShader: SKY_SHADERS.fragment, uniforms: shared,
    side: BackSide, depthWrite: false,
  });
  const scene = new Scene();
  const sky = new Mesh(new SphereGeometry(40, 32, 16), skyMaterial);
  sky.renderOrder = -1;
  const sphere = new Mesh(new SphereGeometry(1, 96, 64), sphereMaterial);
  scene.add(sky, sphere);

  const view = { azimuth: 0, elevation: 15, distance: 6 };
  const size = { width: 1, height: 1 };

  function placeCamera() {
    camera.position.copy(directionFromAngles(view.azimuth, view.elevation)).multiplyScalar(view.distance);
    camera.lookAt(0, 0, 0);
  }

  function draw() {
    const w = size.width / 3;
    camera.aspect = w / size.height;
    camera.updateProjectionMatrix();
    renderer.clear();
    SPHERE_MODES.forEach((_, i) => {
      renderer.setViewport(i * w, 0, w, size.height);
      renderer.setScissor(i * w, 0, w, size.height);
      uniforms.uMode.value = i;
      renderer.render(scene, camera);
    });
    onFrame?.();
  }
  const frames = onDemand(draw);

  const resizeObserver = new ResizeObserver(() => {
    const rect = canvas.getBoundingClientRect();
    size.width = Math.max(3, Math.round(rect.width));
    size.height = Math.max(1, Math.round(rect.height));
    renderer.setPixelRatio(cappedPixelRatio(size.width, size.height, window.devicePixelRatio));
    renderer.setSize(size.width, size.height, false);
    frames.request();
  });
  resizeObserver.observe(canvas);

  // Orbit by pointer drag and by arrow keys (the canvas is focusable); wheel zooms.
  let drag = null;
  const onPointerDown = (event) => {
    drag = { x: event.clientX, y: event.clientY, azimuth: view.azimuth, elevation: view.elevation };
    canvas.setPointerCapture(event.pointerId);
  };
  const onPointerMove = (event) => {
    if (!drag) return;
    const scale = 180 / Math.max(200, size.height);
    setView({
      azimuth: drag.azimuth - (event.clientX - drag.x) * scale,
      elevation: drag.elevation + (event.clientY - drag.y) * scale,
    });
  };
  const onPointerUp = () => { drag = null; };
  const onWheel = (event) => {
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
    frames.request();
    if (!silent) onChange?.({ ...view });
  }

  const raycaster = new Raycaster();
  const unitSphere = new Sphere(new Vector3(), 1);
  const ndc = new Vector2();
  const hit = new Vector3();

  return {
    renderer,
    frames,
    get view() { return { ...view }; },
    setView,
    /** Updates the optics and look; values as in the panel's params (colours linear after Color.set). */
    setParams({ nI, nT, kd, ks, sunDir, envStrength, errScale }) {
      uniforms.uNI.value = nI;
      uniforms.uNT.value = nT;
      uniforms.uKd.value.set(kd);
      uniforms.uKs.value.set(ks);
      shared.uSunDir.value.copy(sunDir);
      shared.uEnvStrength.value = envStrength;
      uniforms.uErrScale.value = errScale;
      frames.request();
    },
    /** Which sphere is under a client point, and the cos θ between its normal and the view there. */
    pick(clientX, clientY) {
      const rect = canvas.getBoundingClientRect();
      const w = rect.width / 3;
      const index = Math.floor((clientX - rect.left) / w);
      if (index < 0 || index > 2) return null;
      ndc.set(((clientX - rect.left - index * w) / w) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
      camera.aspect = w / rect.height;
      camera.updateProjectionMatrix();
      raycaster.setFromCamera(ndc, camera);
      if (!raycaster.ray.intersectSphere(unitSphere, hit)) return null;
      const normal = hit.clone().normalize();
      const toEye = camera.position.clone().sub(hit).normalize();
      return { mode: SPHERE_MODES[index], cosTheta: Math.min(1, Math.max(0, normal.dot(toEye))) };
    },
    /** Draws now and reads one pixel (CSS coordinates within the canvas) as [r, g, b, a] bytes. */
    readPixel(x, y) {
      draw();
      return readPixel(renderer, x, y, size.height);
    },
    /** Draws now and returns the canvas as a PNG data URL (the drawing buffer is not preserved). */
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      frames.cancel();
      resizeObserver.disconnect();
      canvas.removeEventListener('pointerdown', onPointerDown);
      canvas.removeEventListener('pointermove', onPointerMove);
      canvas.removeEventListener('pointerup', onPointerUp);
      canvas.removeEventListener('pointercancel', onPointerUp);
      canvas.removeEventListener('wheel', onWheel);
      canvas.removeEventListener('keydown', onKeyDown);
      sphere.geometry.dispose();
      sky.geometry.dispose();
      sphereMaterial.dispose();
      skyMaterial.dispose();
      renderer.dispose();
    },
  };
}
