// A full-screen triangle as a three.js scene, for the one panel that also needs three.js's
// textures and render targets (normal-mips); panels with only uniforms use createShaderView.js.
import {
  BufferGeometry, Float32BufferAttribute, GLSL3, Mesh, OrthographicCamera, RawShaderMaterial, Scene,
} from 'three';
import { assembleShader } from './shaderChunks.js';

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
