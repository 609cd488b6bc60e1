// A canvas drawn by one full-screen fragment shader: the cheapest scene for panels whose picture
// is analytic (a ray-traced plane, a wave field, a lit sphere on a flat background). Renders on
// demand, counts against the context budget, and can read pixels back for tests and exports.
import {
  BufferGeometry, Float32BufferAttribute, GLSL3, Mesh, OrthographicCamera, RawShaderMaterial, Scene, Vector2,
} from 'three';
import { assembleShader } from './shaderChunks.js';
import { cappedPixelRatio, createRenderer } from './createRenderer.js';
import { onDemand } from './onDemand.js';
import { readPixel } from './readPixel.js';

/** The vertex shader of a full-screen triangle: vUv runs 0..1 across the canvas. */
export const FULLSCREEN_VERTEX_GLSL = `precision highp float;
in vec3 position;
out vec2 vUv;
void main() {
  vUv = position.xy * 0.5 + 0.5;
  gl_Position = vec4(position.xy, 0.0, 1.0);
}`;

/**
 * One full-screen triangle drawn by the GLSL `fragment` (its includes resolved by assembleShader) with these
 * three.js uniforms: { scene, camera, material, dispose() } for renderer.render(scene, camera).
 */
export function createFullscreenPass(fragment, uniforms) {
  const material = new RawShaderMaterial({
    glslVersion: GLSL3, vertexShader: FULLSCREEN_VERTEX_GLSL, fragmentShader: assembleShader(fragment), uniforms,
    depthTest: false, depthWrite: false,
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
  const mesh = new Mesh(geometry, material);
  mesh.frustumCulled = false;
  const scene = new Scene();
  scene.add(mesh);
  return {
    scene,
    camera: new OrthographicCamera(),
    material,
    dispose() {
      geometry.dispose();
      material.dispose();
    },
  };
}

/**
 * fragment: GLSL source (a panel's `.glsl` file imported with `?raw`). It receives `in vec2 vUv` (0..1 across
 * the canvas) and `uniform vec2 uResolution` (drawing-buffer pixels), and declares `out vec4`.
 * uniforms: three.js uniforms ({ name: { value } }); call render() after changing them.
 * @param {HTMLCanvasElement} canvas
 * @param {{ fragment: string, uniforms?: Record<string, { value: any }>, onFrame?: () => void, maxPixels?: number }} options
 */
export function createShaderView(canvas, { fragment, uniforms = {}, onFrame, maxPixels = 1_500_000 }) {
  const renderer = createRenderer(canvas, { antialias: false });
  const allUniforms = { ...uniforms, uResolution: { value: [1, 1] } };
  const pass = createFullscreenPass(fragment, allUniforms);
  const { scene, camera } = pass;
  const size = { width: 1, height: 1 };

  function draw() {
    renderer.clear();
    renderer.render(scene, camera);
    onFrame?.();
  }
  const frames = onDemand(draw);

  const resizeObserver = new ResizeObserver(() => {
    const rect = canvas.getBoundingClientRect();
    size.width = Math.max(1, Math.round(rect.width));
    size.height = Math.max(1, Math.round(rect.height));
    renderer.setPixelRatio(cappedPixelRatio(size.width, size.height, window.devicePixelRatio, 2, maxPixels));
    renderer.setSize(size.width, size.height, false);
    const buffer = renderer.getDrawingBufferSize(new Vector2());
    allUniforms.uResolution.value = [buffer.x, buffer.y];
    frames.request();
  });
  resizeObserver.observe(canvas);

  return {
    renderer,
    uniforms: allUniforms,
    frames,
    /** Schedules one frame (coalesced with any others this animation frame). */
    render: () => frames.request(),
    /** Draws now and reads one pixel at CSS coordinates within the canvas: [r, g, b, a] bytes. */
    readPixel(x, y) {
      draw();
      return readPixel(renderer, x, y, size.height);
    },
    /** Draws now and returns a PNG data URL (the drawing buffer is not preserved between frames). */
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      frames.cancel();
      resizeObserver.disconnect();
      pass.dispose();
      renderer.dispose();
    },
  };
}
