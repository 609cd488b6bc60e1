// Frame cost of the hero view (src/panels/spheres/createSphereTrio.js: three analytic spheres over
// a kept sky) against three spheres of three.js's MeshPhysicalMaterial drawn the ordinary way
// (createPhysicalPeer.js), with and without a clear coat, at the same canvas size, in the same run.
// Where the time goes: the hero's frame after a change of n (the squares round the spheres over the
// kept sky), after a change of the view (the sky drawn again first), and as one full-screen pass of
// the whole picture; and the floor, one full-screen pass that copies the finished picture from a
// texture, which any method that redraws every pixel pays. Timed by the GPU timer query around the
// draw calls alone where the browser offers it (the read-back that ends a frame is outside the
// query: inside it, the query measured the wait for the CPU too), else by wall clock from the
// draw calls to a 1-pixel read-back (the same sync cost on every side). The median over frames is
// reported. It imports the hero's scene and schema from src/panels/spheres/ (the one place a panel
// reaches into another). The peer (and three.js with it) is loaded when a run gets to it.
import { createSphereTrio } from '../spheres/createSphereTrio.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { createProgram } from '../../gl/createProgram.js';
import COPY from '../../gl/copyTexel.frag.glsl?raw';
import { TIMER_QUERY, WALL_TIMER } from '../../gl/timeMethodsGpu.js';
import { spreadOf } from '../../methods/timeMethodsCpu.js';
import { schema as heroSchema } from '../spheres/schema.js';
import { defaults as defaultValues } from '../../host/params.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

const defaults = defaultValues(heroSchema);
const SUN = directionFromAngles(defaults.lightAz, defaults.lightEl);
const INDICES = [defaults.nT, defaults.nT + 0.1]; // a change of n every frame, between two values
const nextFrame = () => new Promise((resolve) => { requestAnimationFrame(() => resolve()); });
const sync = (gl) => gl.readPixels(1, 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));

/** A canvas of this CSS size in host, laid out but not seen (ResizeObserver needs a real box). */
function stageCanvas(host, width, height) {
  const canvas = document.createElement('canvas');
  canvas.className = 'sa-frame-canvas';
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  canvas.setAttribute('aria-hidden', 'true');
  host.append(canvas);
  return canvas;
}

/** GPU ms of one frame's draw calls by EXT_disjoint_timer_query_webgl2, or NaN (disjoint: the result is void). */
async function gpuTime(gl, ext, draw) {
  const query = gl.createQuery();
  gl.beginQuery(ext.TIME_ELAPSED_EXT, query);
  draw();
  gl.endQuery(ext.TIME_ELAPSED_EXT);
  sync(gl); // the frame is finished before the next begins
  while (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) await new Promise((r) => { setTimeout(r, 0); });
  const ms = gl.getParameter(ext.GPU_DISJOINT_EXT) ? NaN : gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6;
  gl.deleteQuery(query);
  return ms;
}

/** Frame times by the timer query where offered (as timeMethodsGpu), else by wall clock. draw(i): frame i. */
async function timeDraws(gl, draw, { frames, warmup, signal, now }) {
  const ext = gl.getExtension(TIMER_QUERY);
  for (let i = 0; i < warmup; i += 1) {
    draw(i);
    sync(gl);
  }
  const samples = [];
  for (let i = 0; i < frames; i += 1) {
    signal?.throwIfAborted();
    if (ext) {
      samples.push(await gpuTime(gl, ext, () => draw(warmup + i)));
    } else {
      const t0 = now();
      draw(warmup + i);
      sync(gl);
      samples.push(now() - t0);
    }
    if (i % 4 === 3) await nextFrame(); // let the page breathe (and the progress bar move)
  }
  return { msPerFrame: spreadOf(samples), samples, timer: ext ? TIMER_QUERY : WALL_TIMER };
}

/** The floor: one full-screen pass copying the hero's finished picture from a texture. */
async function copyFrames(gl, options) {
  const { drawingBufferWidth: width, drawingBufferHeight: height } = gl;
  const texture = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGB8, width, height);
  gl.copyTexSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 0, 0, width, height); // the picture just drawn
  const program = createProgram(gl, COPY);
  try {
    program.setUniforms({ uPicture: { value: 0 } });
    return await timeDraws(gl, () => {
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, texture);
      program.draw();
    }, options);
  } finally {
    program.dispose();
    gl.deleteTexture(texture);
  }
}

/** The hero's own view with its default parameters: its three kinds of frame, and the floor. */
async function heroFrames(host, size, options, progress) {
  const canvas = stageCanvas(host, size.width, size.height);
  const trio = createSphereTrio(canvas);
  const params = {
    nI: defaults.nI, nT: defaults.nT, kd: defaults.kd, ks: defaults.ks, sunDir: SUN, envStrength: defaults.env, errScale: 0.05,
  };
  const view = { azimuth: defaults.viewAz, elevation: defaults.viewEl, distance: defaults.viewDist };
  try {
    trio.setParams(params);
    trio.setView(view, { silent: true });
    await nextFrame(); // the ResizeObserver sizes the drawing buffer
    await nextFrame();
    const { gl } = trio.shaderView;
    const pixels = gl.drawingBufferWidth * gl.drawingBufferHeight;
    const timed = async (step, draw) => {
      progress(step);
      return { ...(await timeDraws(gl, draw, options)), pixels };
    };
    const spheres = await timed('frameHero', (i) => {
      trio.setParams({ ...params, nT: INDICES[i % 2] });
      trio.shaderView.drawNow();
    });
    const spheresView = await timed('frameHeroView', (i) => {
      trio.setView({ azimuth: view.azimuth + (i % 2) }, { silent: true });
      trio.shaderView.drawNow();
    });
    const spheresOnePass = await timed('frameHeroOnePass', () => trio.shaderView.drawOnePass());
    progress('frameCopy');
    trio.shaderView.drawNow();
    const copy = { ...(await copyFrames(gl, options)), pixels };
    return { spheres, spheresView, spheresOnePass, copy };
  } finally {
    trio.dispose();
    canvas.remove();
  }
}

/** Three MeshPhysicalMaterial spheres, with a clear coat (a coated red plastic, like the hero's) or without. */
async function physicalFrames(host, size, options, clearcoat) {
  // three.js comes only with a benchmark run: the panel itself does not need it.
  const { createPhysicalPeer } = await import('./createPhysicalPeer.js');
  const canvas = stageCanvas(host, size.width, size.height);
  const peer = createPhysicalPeer(canvas, { width: size.width, height: size.height, nT: defaults.nT, color: defaults.kd, clearcoat });
  try {
    const gl = peer.renderer.getContext();
    const result = await timeDraws(gl, () => peer.drawNow(), options);
    return { ...result, pixels: peer.drawingBufferPixels() };
  } finally {
    peer.dispose();
    canvas.remove();
  }
}

const STEPS = ['frameHero', 'frameHeroView', 'frameHeroOnePass', 'frameCopy', 'framePeer', 'framePeerPlain'];

/**
 * Times the hero and its peers at width × height CSS pixels in host (a laid-out element; the
 * canvases are added and removed). Options: frames, warmup, signal, onProgress(done, total, label),
 * whenVisible (awaited before each scene), now.
 * Resolves to { spheres (a frame after a change of n), spheresView (after a change of the view),
 * spheresOnePass (the whole picture in one pass), copy (the floor), threePhysical (clear coat),
 * threePlain (none): each { msPerFrame: { median, min, max }, samples, pixels, timer }; ratio:
 * spheres / threePhysical and plainRatio: spheres / threePlain (medians; below 1: the hero is
 * cheaper), width, height }.
 * @param {HTMLElement} host
 * @param {{ width?: number, height?: number, frames?: number, warmup?: number, signal?: AbortSignal,
 *   onProgress?: (done: number, total: number, label?: string) => void, whenVisible?: () => Promise<void>,
 *   now?: () => number }} [options]
 * @returns {Promise<import('../../methods/benchResults.js').FrameTimings>}
 */
export async function timeFrames(host, {
  width = 900, height = 300, frames = 12, warmup = 3, signal, onProgress, whenVisible, now = () => performance.now(),
} = {}) {
  const size = { width, height };
  const options = { frames, warmup, signal, now };
  const progress = (step) => onProgress?.(STEPS.indexOf(step), STEPS.length, t(step));
  await whenVisible?.();
  const hero = await heroFrames(host, size, options, progress);
  signal?.throwIfAborted();
  await whenVisible?.();
  progress('framePeer');
  const threePhysical = await physicalFrames(host, size, options, true);
  signal?.throwIfAborted();
  await whenVisible?.();
  progress('framePeerPlain');
  const threePlain = await physicalFrames(host, size, options, false);
  onProgress?.(STEPS.length, STEPS.length, t('frameDone'));
  const median = (side) => side.msPerFrame.median;
  return {
    ...hero, threePhysical, threePlain,
    ratio: median(hero.spheres) / median(threePhysical), plainRatio: median(hero.spheres) / median(threePlain), width, height,
  };
}
