// The still part of a picture, kept between frames. For a fragment most of whose pixels no `live`
// uniform touches (the hero's sky around its spheres), those pixels are drawn once into an RGBA8
// target by the fragment compiled with BACKDROP_PASS, and each frame copies them to the canvas (a
// full-screen pass of one texel fetch: on a software rasterizer it costs less than blitFramebuffer,
// on a GPU both are nearly free); the fragment compiled with BACKDROP is then drawn only inside `regions`, where the live
// uniforms show, and may read the kept pixels from `uniform sampler2D uBackdrop`. The target holds
// the very bytes the canvas would have shown, so the picture is the one-pass picture; a change of
// any other uniform (or of the size) draws the kept pixels again.
import { createFloatTarget } from './createFloatTarget.js';
import { createProgram } from './createProgram.js';
import COPY from './copyTexel.frag.glsl?raw';


/**
 * @param {WebGL2RenderingContext} gl
 * @param {string} source the fragment, includes resolved
 * @param {{ live: string[], regions: (width: number, height: number) => number[][] }} options regions
 *   gives [x, y, width, height] rectangles of drawing-buffer pixels (origin bottom left) outside
 *   which the picture depends on no live uniform.
 */
export function createBackdrop(gl, source, { live, regions }) {
  const program = createProgram(gl, `#define BACKDROP_PASS\n${source}`);
  const copyProgram = createProgram(gl, COPY);
  const target = createFloatTarget(gl, gl.RGBA8);
  let key = null;
  let drawn = 0;
  return {
    /** How many times the kept pixels were drawn. */
    get drawn() { return drawn; },
    /**
     * Puts the kept pixels on the canvas, drawing them first when a still uniform or the size has
     * changed; returns the rectangles to draw over them, clipped to the drawing buffer. The kept
     * pixels stay bound to texture unit 0.
     * @param {Record<string, { value: any }>} uniforms
     */
    copy(uniforms) {
      const width = gl.drawingBufferWidth;
      const height = gl.drawingBufferHeight;
      const next = JSON.stringify(Object.entries(uniforms).filter(([name]) => !live.includes(name)));
      if (next !== key || target.width !== width || target.height !== height) {
        if (target.width !== width || target.height !== height) target.setSize(width, height);
        gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
        gl.viewport(0, 0, width, height);
        program.setUniforms(uniforms);
        program.draw();
        key = next;
        drawn += 1;
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.viewport(0, 0, width, height);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, target.texture);
      copyProgram.setUniforms({ uPicture: { value: 0 } });
      copyProgram.draw();
      return regions(width, height).map(([x, y, w, h]) => {
        const x0 = Math.max(0, Math.floor(x));
        const y0 = Math.max(0, Math.floor(y));
        return [x0, y0, Math.max(0, Math.min(width, Math.ceil(x + w)) - x0), Math.max(0, Math.min(height, Math.ceil(y + h)) - y0)];
      }).filter(([, , w, h]) => w > 0 && h > 0);
    },
    dispose() {
      program.dispose();
      copyProgram.dispose();
      target.dispose();
    },
  };
}
