// GPU cost of every Fresnel method on the device in front of the viewer, measured with a large
// workload so that the GPU really does the work (gman, webglfundamentals "How do I benchmark a
// WebGL shader?"): one full-screen pass per method and precision that evaluates the
// method `loops` times per pixel (a uniform loop count, so nothing is unrolled or folded), with
// inputs that vary per pixel (from gl_FragCoord) and an input for each iteration that depends on
// the previous result (so nothing can be hoisted), every result accumulated into the output (so
// nothing is dead code), minus a baseline pass of the same shape with F(c) = c. The pass is timed
// with EXT_disjoint_timer_query_webgl2 where the browser offers it, else by wall time around a
// block of passes fenced by 1-pixel readPixels (the dependable sync point: it must wait for the
// pixels, same source). Each sample is the
// fastest of a few timings (other work on the machine only ever adds time), baseline and method
// back to back. Reported: ns per evaluation { median, min, max } over repeats, and the timer used.
// The method code is the shared GLSL twin, shaders/fresnelMethods.glsl (`#include <fresnelMethods>`).
import { f82Coefficients, METHODS } from '../methods/methods.js';
import { sceneById } from '../methods/scenes.js';
import { spreadOf } from '../methods/timeMethodsCpu.js';
import { checkProgram, compileProgram, createFullScreenTriangle } from './compileProgram.js';
import { glslFunctionName, GPU_PRECISIONS } from './methodIndex.js';
import { resolveIncludes } from './resolveIncludes.js';
import { shaderChunks } from './shaderChunks.js';
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

export { GPU_PRECISIONS };
export const TIMER_QUERY = 'EXT_disjoint_timer_query_webgl2';
// The timer as results record it (data: the same in every language); timerName says it in words.
export const WALL_TIMER = 'wall clock around passes fenced by a 1-pixel readPixels';

/** A recorded timer in the page's language: the wall clock in words, an extension by its name. */
export const timerName = (timer) => (timer === WALL_TIMER ? t('wallClock') : timer);

/**
 * GLSL for one evaluation of a method on c and the per-pixel arguments v (vec4), calling its own
 * function of fresnelMethods.glsl (not the fm_evaluate selector, whose branches would be timed
 * too): dielectrics fm_<id>(c, nI, nT), conductors fm_<id>(c, n, k, f0, b).
 */
export function methodCall(method) {
  const fn = glslFunctionName(method.id);
  return method.kind === 'dielectric' ? `${fn}(c, v.x, v.y)` : `${fn}(c, v.x, v.y, v.z, v.w)`;
}

/**
 * The timing fragment shader: `call` evaluated uLoops times (null: the baseline F(c) = c) under
 * `precision float` ('highp' | 'mediump'). Arguments v run from uLo to uHi down the target, c
 * across it; each next c is fract(0.618c + F + 0.1), so it depends on the last result.
 */
export function timingFragment(call, precision, chunks = shaderChunks) {
  if (!GPU_PRECISIONS.includes(precision)) throw new RangeError(`precision must be highp or mediump, got ${precision}`);
  return resolveIncludes(`#version 300 es
precision ${precision} float;
precision highp int;
${call ? '#include <fresnelMethods>' : ''}
uniform int uLoops;
uniform highp vec2 uSize;
uniform vec4 uLo;
uniform vec4 uHi;
out vec4 outColor;
void main() {
  highp vec2 p = gl_FragCoord.xy / uSize;
  vec4 v = mix(uLo, uHi, p.y);
  float c = p.x;
  float sum = 0.0;
  for (int i = 0; i < uLoops; i++) {
    float f = ${call ?? 'c'};
    sum += f;
    c = fract(c * 0.618034 + f + 0.1);
  }
  outColor = vec4(fract(sum), c, 0.0, 1.0);
}`, chunks);
}

/** Argument ranges per kind: dielectric (nI, nT) over the plastic scene (air → 1.3 … 1.7);
 *  conductor (n, k, F0, F82 b) from gold to aluminium at 550 nm (the metal scene's cases). */
export function timingDomain(kind) {
  if (kind === 'dielectric') {
    const nT = sceneById('plastic').cases.map((c) => c[1]);
    return { lo: [1, Math.min(...nT), 0, 0], hi: [1, Math.max(...nT), 0, 0] };
  }
  const [gold, aluminium] = [sceneById('metal').cases[1], sceneById('metal').cases[4]];
  const args = ([n, k, f0]) => [n, k, f0, f82Coefficients(n, k, f0).b];
  return { lo: args(gold), hi: args(aluminium) };
}

/**
 * The renderer and vendor strings (unmasked where the browser masks gl.RENDERER).
 * @param {WebGL2RenderingContext} gl
 * @returns {{ renderer: string, vendor: string, version: string }}
 */
export function deviceInfo(gl) {
  let renderer = gl.getParameter(gl.RENDERER);
  let vendor = gl.getParameter(gl.VENDOR);
  if (renderer === 'WebKit WebGL') {
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    if (info) {
      renderer = gl.getParameter(info.UNMASKED_RENDERER_WEBGL);
      vendor = gl.getParameter(info.UNMASKED_VENDOR_WEBGL);
    }
  }
  return { renderer: String(renderer), vendor: String(vendor), version: String(gl.getParameter(gl.VERSION)) };
}

const pause = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/**
 * Times methods on a WebGL2 context (the caller owns it). Options: methods (default all),
 * precisions (default both), size (target is size × size), loops (starting loop count; it is
 * calibrated so the costliest pass takes about targetMs), passes (draws per wall-clock block),
 * bestOf (timings per sample, the fastest kept: interference only ever adds time), repeats, maxLoops,
 * onProgress(done, total, label), signal (AbortSignal), whenVisible (awaited after each method: the
 * run pauses while its panel is off screen), chunks (shader chunks, for tests), now (ms clock).
 * Resolves to { timer, device, size, loops, passes, bestOf, repeats, evaluationsPerPass,
 * results: { highp: { id: { nsPerEval, samples } }, mediump: … }, baselineMs }.
 * @param {WebGL2RenderingContext} gl
 * @param {{ methods?: readonly import('../methods/methods.js').Method[], precisions?: readonly string[], size?: number,
 *   loops?: number, targetMs?: number, passes?: number, bestOf?: number, repeats?: number, maxLoops?: number,
 *   onProgress?: (done: number, total: number, label?: string) => void, signal?: AbortSignal,
 *   whenVisible?: () => Promise<void>, chunks?: Record<string, string>, now?: () => number }} [options]
 * @returns {Promise<import('../methods/benchResults.js').GpuTimings>}
 */
export async function timeMethodsGpu(gl, {
  methods = METHODS, precisions = GPU_PRECISIONS, size = 128, loops = 16, targetMs = 5, passes = 2, bestOf = 3, repeats = 5,
  maxLoops = 1 << 14, onProgress, signal, whenVisible, chunks = shaderChunks, now = () => performance.now(),
} = {}) {
  const ext = gl.getExtension(TIMER_QUERY);
  const timer = ext ? TIMER_QUERY : WALL_TIMER;
  const target = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, size, size);
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  const triangle = createFullScreenTriangle(gl);
  gl.viewport(0, 0, size, size);
  gl.disable(gl.DEPTH_TEST);
  gl.disable(gl.BLEND);
  gl.disable(gl.SCISSOR_TEST);
  const query = ext ? gl.createQuery() : null;
  const pixel = new Uint8Array(4);
  const programs = [];
  const sync = () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);

  try {
    // Compile everything first (in parallel where the driver can), then check.
    const entries = [];
    const start = (precision, id, kind, call) => {
      const program = compileProgram(gl, timingFragment(call, precision, chunks), { check: false });
      programs.push(program);
      entries.push({ precision, id, kind, program });
    };
    for (const precision of precisions) {
      start(precision, 'baseline', null, null);
      for (const m of methods) start(precision, m.id, m.kind, methodCall(m));
    }
    const passName = (id) => (id === 'baseline' ? t('baselinePass') : methods.find((m) => m.id === id).label);
    for (const e of entries) checkProgram(gl, e.program, { label: t('timingPass', { method: passName(e.id), precision: e.precision }) });
    // A lost context refuses nothing (checkProgram), but its timer query would never answer.
    if (gl.isContextLost()) throw new Error(t('contextLost'));
    const find = (precision, id) => entries.find((e) => e.precision === precision && e.id === id);

    let loopCount = loops;
    const draw = (entry) => {
      gl.useProgram(entry.program);
      const domain = timingDomain(entry.kind ?? 'dielectric');
      gl.uniform1i(gl.getUniformLocation(entry.program, 'uLoops'), loopCount);
      gl.uniform2f(gl.getUniformLocation(entry.program, 'uSize'), size, size);
      gl.uniform4fv(gl.getUniformLocation(entry.program, 'uLo'), domain.lo);
      gl.uniform4fv(gl.getUniformLocation(entry.program, 'uHi'), domain.hi);
      triangle.draw();
    };
    /** ms for one pass (timer query) or for `passes` passes (wall clock). */
    const time = async (entry) => {
      if (ext) {
        for (let attempt = 0; attempt < 4; attempt += 1) {
          gl.getParameter(ext.GPU_DISJOINT_EXT); // clears a stale disjoint flag
          gl.beginQuery(ext.TIME_ELAPSED_EXT, query);
          draw(entry);
          gl.endQuery(ext.TIME_ELAPSED_EXT);
          gl.flush();
          while (!gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) await pause();
          // Disjoint is checked after availability (KhronosGroup/WebGL #3497); such a result is void.
          if (!gl.getParameter(ext.GPU_DISJOINT_EXT)) return gl.getQueryParameter(query, gl.QUERY_RESULT) / 1e6;
        }
        return NaN;
      }
      sync();
      const t0 = now();
      for (let i = 0; i < passes; i += 1) draw(entry);
      sync();
      return (now() - t0) / passes;
    };
    const best = async (entry) => {
      let ms = Infinity;
      for (let i = 0; i < bestOf; i += 1) ms = Math.min(ms, await time(entry));
      return ms;
    };

    // Warm up every program once (first draws pay for lazy compilation), then calibrate the
    // loop count on the costliest method so its pass takes about targetMs.
    for (const e of entries) draw(e);
    sync();
    const costliest = [...methods].sort((a, b) => b.cost.static - a.cost.static)[0];
    const probe = find(precisions[0], costliest?.id ?? 'baseline');
    for (let i = 0; i < 8; i += 1) {
      const ms = await time(probe);
      if (!(ms < targetMs / 2) || loopCount >= maxLoops) break;
      loopCount = Math.min(maxLoops, Math.max(loopCount * 2, Math.round((loopCount * targetMs) / Math.max(ms, 0.05))));
      signal?.throwIfAborted();
    }

    const evaluations = size * size * loopCount;
    const samples = Object.fromEntries(precisions.map((p) => [p, Object.fromEntries(methods.map((m) => [m.id, []]))]));
    const baseline = [];
    const total = repeats * precisions.length * methods.length;
    let done = 0;
    for (let r = 0; r < repeats; r += 1) {
      for (const precision of precisions) {
        for (const m of methods) {
          signal?.throwIfAborted();
          // Baseline and method back to back, so a drift of the clock hits both alike.
          const base = await best(find(precision, 'baseline'));
          const ms = await best(find(precision, m.id));
          baseline.push(base);
          samples[precision][m.id].push(((ms - base) * 1e6) / evaluations);
          done += 1;
          onProgress?.(done, total, t('timingProgress', { method: m.label, precision }));
          await pause();
          await whenVisible?.();
        }
      }
    }
    signal?.throwIfAborted();
    const results = Object.fromEntries(precisions.map((p) => [p, Object.fromEntries(methods.map((m) => [
      m.id, { nsPerEval: spreadOf(samples[p][m.id]), samples: samples[p][m.id] },
    ]))]));
    return {
      timer, device: deviceInfo(gl), size, loops: loopCount, passes: ext ? 1 : passes, bestOf, repeats,
      evaluationsPerPass: evaluations, results, baselineMs: spreadOf(baseline),
    };
  } finally {
    for (const program of programs) gl.deleteProgram(program);
    if (query) gl.deleteQuery(query);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fbo);
    gl.deleteTexture(target);
    triangle.dispose();
  }
}
