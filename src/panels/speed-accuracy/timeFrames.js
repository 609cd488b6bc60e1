// Frame cost of the hero view (src/panels/spheres/createSphereTrio.js: three analytic spheres in
// one full-screen pass) against three spheres of three.js's MeshPhysicalMaterial drawn the ordinary
// way (createPhysicalPeer.js), at the same canvas size, in the same run. Each frame is drawn and
// fenced by a 1-pixel readPixels, and timed by the GPU timer query where the browser offers it (GPU
// time only), else by wall clock (GPU time plus the same sync cost on both sides); the median over
// frames is reported. It measures the hero itself, so it imports the hero's scene and schema from
// src/panels/spheres/ (the one place a panel reaches into another). The peer (and three.js with it)
// is loaded when a run gets to it.
import { createSphereTrio } from '../spheres/createSphereTrio.js';
import { directionFromAngles } from '../../gl/directionFromAngles.js';
import { TIMER_QUERY, WALL_TIMER } from '../../gl/timeMethodsGpu.js';
import { spreadOf } from '../../methods/timeMethodsCpu.js';
import { schema as heroSchema } from '../spheres/schema.js';
import { defaults as defaultValues } from '../../host/params.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

const defaults = defaultValues(heroSchema);
const SUN = directionFromAngles(defaults.lightAz, defaults.lightEl);
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

/** GPU ms of one frame by EXT_disjoint_timer_query_webgl2, or NaN (disjoint: the result is void). */
async function gpuTime(gl, ext, drawAndSync) {
  const query = gl.createQuery();
  gl.beginQuery(ext.TIME_ELAPSED_EXT, query);
  drawAndSync();
  gl.endQuery(ext.TIME_ELAPSED_EXT);
  while (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) await new Promise((r) => { setTimeout(r, 0); });
  const ms = gl.getParameter(ext.GPU_DISJOINT_EXT) ? NaN : gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6;
  gl.deleteQuery(query);
  return ms;
}

/** Frame times by the timer query where offered (as timeMethodsGpu), else by wall clock. */
async function timeDraws(gl, drawAndSync, { frames, warmup, signal, now }) {
  const ext = gl.getExtension(TIMER_QUERY);
  for (let i = 0; i < warmup; i += 1) drawAndSync();
  const samples = [];
  for (let i = 0; i < frames; i += 1) {
    signal?.throwIfAborted();
    if (ext) {
      samples.push(await gpuTime(gl, ext, drawAndSync));
    } else {
      const t0 = now();
      drawAndSync();
      samples.push(now() - t0);
    }
    if (i % 4 === 3) await nextFrame(); // let the page breathe (and the progress bar move)
  }
  return { msPerFrame: spreadOf(samples), samples, timer: ext ? TIMER_QUERY : WALL_TIMER };
}

/** The hero's own view, with its default parameters. */
async function heroFrames(host, size, options) {
  const canvas = stageCanvas(host, size.width, size.height);
  const trio = createSphereTrio(canvas);
  try {
    trio.setParams({
      nI: defaults.nI, nT: defaults.nT, kd: defaults.kd, ks: defaults.ks, sunDir: SUN, envStrength: defaults.env, errScale: 0.05,
    });
    trio.setView({ azimuth: defaults.viewAz, elevation: defaults.viewEl, distance: defaults.viewDist }, { silent: true });
    await nextFrame(); // the ResizeObserver sizes the drawing buffer
    await nextFrame();
    const { gl } = trio.shaderView;
    const result = await timeDraws(gl, () => { trio.shaderView.drawNow(); sync(gl); }, options);
    return { ...result, pixels: gl.drawingBufferWidth * gl.drawingBufferHeight };
  } finally {
    trio.dispose();
    canvas.remove();
  }
}

/** Three MeshPhysicalMaterial spheres (a clear-coated red plastic, like the hero's). */
async function physicalFrames(host, size, options) {
  // three.js comes only with a benchmark run: the panel itself does not need it.
  const { createPhysicalPeer } = await import('./createPhysicalPeer.js');
  const canvas = stageCanvas(host, size.width, size.height);
  const peer = createPhysicalPeer(canvas, { width: size.width, height: size.height, nT: defaults.nT, color: defaults.kd });
  try {
    const gl = peer.renderer.getContext();
    const result = await timeDraws(gl, () => { peer.drawNow(); sync(gl); }, options);
    return { ...result, pixels: peer.drawingBufferPixels() };
  } finally {
    peer.dispose();
    canvas.remove();
  }
}

/**
 * Times both views at width × height CSS pixels in host (a laid-out element; the canvases are
 * added and removed). Options: frames, warmup, signal, onProgress(done, total, label), whenVisible
 * (awaited before each scene), now.
 * Resolves to { spheres, threePhysical (each { msPerFrame: { median, min, max }, samples,
 * pixels, timer }), ratio: spheres median / physical median (below 1: the hero is cheaper), width, height }.
 */
export async function timeFrames(host, {
  width = 900, height = 300, frames = 12, warmup = 3, signal, onProgress, whenVisible, now = () => performance.now(),
} = {}) {
  const size = { width, height };
  const options = { frames, warmup, signal, now };
  onProgress?.(0, 2, t('frameHero'));
  await whenVisible?.();
  const spheres = await heroFrames(host, size, options);
  signal?.throwIfAborted();
  await whenVisible?.();
  onProgress?.(1, 2, t('framePeer'));
  const threePhysical = await physicalFrames(host, size, options);
  onProgress?.(2, 2, t('frameDone'));
  return { spheres, threePhysical, ratio: spheres.msPerFrame.median / threePhysical.msPerFrame.median, width, height };
}
