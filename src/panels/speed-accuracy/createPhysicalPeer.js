// The peer the hero is measured against: three glossy spheres the ordinary three.js way, as a user
// of the same stack would write them. MeshPhysicalMaterial (its Fresnel is three.js's Schlick,
// from ior) on a 64×32-segment sphere, lit by RoomEnvironment prefiltered through PMREM, a sun,
// one camera and one antialiased canvas, rendered on demand. Its background is a flat colour, so
// the comparison, if anything, favours the peer. The benchmark page (bench/peer.html)
// and the speed-accuracy panel's frame timing both draw this scene.
import {
  Color, DirectionalLight, Mesh, MeshPhysicalMaterial, PerspectiveCamera, PMREMGenerator, Scene, SphereGeometry, Vector2,
} from 'three';
import { RoomEnvironment } from 'three/examples/jsm/environments/RoomEnvironment.js';
import { cappedPixelRatio } from '../../gl/cappedPixelRatio.js';
import { createRenderer } from '../../gl/createRenderer.js';
import { onDemand } from '../../gl/onDemand.js';

/** canvas: sized by CSS (width × height); the peer draws at its size, capped like the hero. */
export function createPhysicalPeer(canvas, {
  width, height, nT = 1.5, color = '#a3241c', clearcoat = true, onFrame,
} = {}) {
  const renderer = createRenderer(canvas, { antialias: true });
  renderer.autoClear = true;
  renderer.setPixelRatio(cappedPixelRatio(width, height, window.devicePixelRatio));
  renderer.setSize(width, height, false);
  const pmrem = new PMREMGenerator(renderer);
  const environment = pmrem.fromScene(new RoomEnvironment(), 0.04).texture;
  const scene = new Scene();
  scene.environment = environment;
  scene.background = new Color(0x8fa9c8); // a flat sky: the peer is spared the hero's environment background
  const geometry = new SphereGeometry(1, 64, 32);
  const material = new MeshPhysicalMaterial({
    color: new Color(color), roughness: 0.5, clearcoat: clearcoat ? 1 : 0, clearcoatRoughness: 0.02, ior: nT,
  });
  for (const x of [-2.3, 0, 2.3]) {
    const sphere = new Mesh(geometry, material);
    sphere.position.x = x;
    scene.add(sphere);
  }
  const sun = new DirectionalLight(0xffffff, 2);
  sun.position.set(0.47, 0.64, 0.6);
  scene.add(sun);
  const camera = new PerspectiveCamera(28, width / height, 0.1, 100);
  camera.position.set(0, 1.3, 7.2); // the row of three spheres fills a 5:2 canvas
  camera.lookAt(0, 0, 0);
  const draw = () => {
    renderer.render(scene, camera);
    onFrame?.();
  };
  const frames = onDemand(draw);
  return {
    renderer,
    frames,
    drawingBufferPixels() {
      const size = renderer.getDrawingBufferSize(new Vector2());
      return size.x * size.y;
    },
    /** Draws now (the buffer is readable until this task ends). */
    drawNow: draw,
    setParams({ nT: next }) {
      material.ior = next; // three.js derives the specular F0 of a dielectric from ior
      frames.request();
    },
    dispose() {
      frames.cancel();
      geometry.dispose();
      material.dispose();
      environment.dispose();
      pmrem.dispose();
      renderer.dispose();
    },
  };
}
