// A canvas drawn by one full-screen fragment shader: the cheapest scene for panels whose picture
// is analytic (ray-cast spheres, a ray-traced plane, a wave field). Plain WebGL2, no three.js:
// no geometry, no depth or stencil buffer, no MSAA (shaders anti-alias their own edges). Renders on
// demand, counts against the context budget, survives a lost context, and reads pixels back for
// tests and exports.
import { createBackdrop } from './createBackdrop.js';
import { cappedPixelRatio } from './cappedPixelRatio.js';
import { createContext } from './createContext.js';
import { createFloatTarget } from './createFloatTarget.js';
import { createProgram } from './createProgram.js';
import { assembleShader } from './shaderChunks.js';
import { onDemand } from './onDemand.js';

/**
 * fragment: GLSL source (a panel's `.glsl` file imported with `?raw`). It receives `in vec2 vUv` (0..1 across
 * the canvas) and `uniform vec2 uResolution` (drawing-buffer pixels), and declares `out vec4`.
 * uniforms: { name: { value } } (numbers, booleans, arrays, {x,y,z} or {r,g,b}); call render() after changing them.
 * cache: { live: [uniform names] } for a fragment that can split its work: compiled with CACHE_PASS
 * it writes per-pixel terms (a vec4) that depend on no `live` uniform, and compiled with CACHED it
 * reads them from `uniform sampler2D uCache` (texelFetch at gl_FragCoord) and finishes the pixel.
 * The terms are drawn again only when another uniform or the size changes, so a change of a live
 * uniform costs the finishing pass alone. Without float render targets (EXT_color_buffer_float) the
 * fragment is compiled with neither define and does everything in one pass. shaders/keptTerms.glsl
 * holds the fragment's side of this.
 * backdrop: { live, regions(width, height) } for a fragment whose live uniforms show only inside
 * some rectangles (createBackdrop.js): the rest is kept and copied, and the fragment is drawn
 * inside the rectangles alone. Not with cache.
 * @param {HTMLCanvasElement} canvas
 * @param {{
 *   fragment: string, uniforms?: Record<string, { value: any }>, onFrame?: () => void, maxPixels?: number,
 *   cache?: { live: string[] }, backdrop?: { live: string[], regions: (width: number, height: number) => number[][] }
 * }} options
 */
export function createShaderView(canvas, {
  fragment, uniforms = {}, onFrame, maxPixels = 1_500_000, cache = null, backdrop = null,
}) {
  if (cache && backdrop) throw new TypeError('A shader view keeps either terms (cache) or a backdrop, not both.');
  const context = createContext(canvas);
  const { gl } = context;
  const source = assembleShader(fragment);
  const cached = () => Boolean(cache && gl.getExtension('EXT_color_buffer_float'));
  let program = null;
  let termsProgram = null;
  let terms = null; // the float target of the cached terms
  let termsKey = null; // the uniforms (but the live ones) and the size they were drawn for
  let termsDrawn = 0;
  let kept = null; // the backdrop (createBackdrop.js)
  let onePass = null; // the fragment without a backdrop, compiled when asked for (drawOnePass)
  function build() {
    const split = cached();
    program = createProgram(gl, split ? `#define CACHED\n${source}` : backdrop ? `#define BACKDROP\n${source}` : source);
    termsProgram = split ? createProgram(gl, `#define CACHE_PASS\n${source}`) : null;
    terms = split ? createFloatTarget(gl) : null;
    termsKey = null;
    kept = backdrop ? createBackdrop(gl, source, backdrop) : null;
    onePass = null;
  }
  build();
  const allUniforms = { ...uniforms, uResolution: { value: [1, 1] } };
  const size = { width: 1, height: 1, ratio: 1 };

  function drawTerms() {
    const key = JSON.stringify(Object.entries(allUniforms).filter(([name]) => !cache.live.includes(name)));
    if (key === termsKey) return;
    if (terms.width !== gl.drawingBufferWidth || terms.height !== gl.drawingBufferHeight) {
      terms.setSize(gl.drawingBufferWidth, gl.drawingBufferHeight);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, terms.framebuffer);
    gl.viewport(0, 0, terms.width, terms.height);
    termsProgram.setUniforms(allUniforms);
    termsProgram.draw();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    termsKey = key;
    termsDrawn += 1;
  }

  // The kept pixels, then the fragment inside each region (the scissor keeps it there).
  function drawOverBackdrop() {
    const regions = kept.copy(allUniforms);
    program.setUniforms({ ...allUniforms, uBackdrop: { value: 0 } });
    gl.enable(gl.SCISSOR_TEST);
    for (const [x, y, w, h] of regions) {
      gl.scissor(x, y, w, h);
      program.draw();
    }
    gl.disable(gl.SCISSOR_TEST);
  }

  function draw() {
    if (gl.isContextLost()) return;
    if (kept) {
      drawOverBackdrop();
      onFrame?.();
      return;
    }
    if (terms) {
      drawTerms();
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, terms.texture);
    }
    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    program.setUniforms(terms ? { ...allUniforms, uCache: { value: 0 } } : allUniforms);
    program.draw();
    onFrame?.();
  }
  const frames = onDemand(draw);

  const resizeObserver = new ResizeObserver(() => {
    const rect = canvas.getBoundingClientRect();
    size.width = Math.max(1, Math.round(rect.width));
    size.height = Math.max(1, Math.round(rect.height));
    size.ratio = cappedPixelRatio(size.width, size.height, window.devicePixelRatio, 2, maxPixels);
    canvas.width = Math.max(1, Math.floor(size.width * size.ratio));
    canvas.height = Math.max(1, Math.floor(size.height * size.ratio));
    allUniforms.uResolution.value = [canvas.width, canvas.height];
    frames.request();
  });
  resizeObserver.observe(canvas);

  // A lost context (a GPU reset, too many tabs) comes back if the page asks for it: keep the
  // canvas, rebuild the program, and draw again.
  const onLost = (event) => {
    event.preventDefault();
    frames.cancel();
  };
  const onRestored = () => {
    build(); // the old programs and target went with the context
    frames.request();
  };
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);

  return {
    gl,
    canvas,
    uniforms: allUniforms,
    frames,
    /** The linked WebGLProgram (tests read back the source the driver compiled). */
    get program() { return program.program; },
    /** How many times the cached terms were drawn (0 without a cache). */
    get termsDrawn() { return termsDrawn; },
    /** How many times the kept backdrop was drawn (0 without one). */
    get backdropDrawn() { return kept?.drawn ?? 0; },
    /**
     * Draws the whole picture in one full-screen pass, backdrop or no (the benchmark times it
     * against the kept backdrop; tests compare the two pictures). Not counted as a frame.
     */
    drawOnePass() {
      if (gl.isContextLost()) return;
      onePass ??= createProgram(gl, source);
      gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
      onePass.setUniforms(allUniforms);
      onePass.draw();
    },
    /** Drawing-buffer pixels per CSS pixel. */
    get pixelRatio() { return size.ratio; },
    /** Schedules one frame (coalesced with any others this animation frame). */
    render: () => frames.request(),
    /** Draws now (the drawing buffer is readable until this task ends). */
    drawNow: draw,
    /** Draws now and reads one pixel at CSS coordinates within the canvas: [r, g, b, a] bytes. */
    readPixel(x, y) {
      draw();
      const out = new Uint8Array(4);
      gl.readPixels(Math.floor(x * size.ratio), Math.floor((size.height - y) * size.ratio), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
      return [...out];
    },
    /** Draws now and returns a PNG data URL (the drawing buffer is not preserved between frames). */
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      frames.cancel();
      resizeObserver.disconnect();
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      program.dispose();
      termsProgram?.dispose();
      terms?.dispose();
      kept?.dispose();
      onePass?.dispose();
      context.dispose();
    },
  };
}
