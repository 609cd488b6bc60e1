// An RGBA32F render target (a texture and its framebuffer, no depth) for passes whose results are
// read back or accumulated in float. Needs EXT_color_buffer_float, which the caller enables.
// With internalFormat RGBA8 it keeps a picture as the canvas would show it (always renderable).
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

/** A read-back that cannot finish: the context was lost while it waited (even if it is back now). */
export class ContextLostError extends Error {}

export function createFloatTarget(gl, internalFormat = gl.RGBA32F) {
  let texture = null;
  let framebuffer = null;
  const target = {
    width: 0,
    height: 0,
    get texture() { return texture; },
    get framebuffer() { return framebuffer; },
    /** (Re)allocates at width × height; the contents are undefined until drawn. */
    setSize(width, height) {
      target.dispose();
      target.width = width;
      target.height = height;
      texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, internalFormat, width, height);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      gl.bindTexture(gl.TEXTURE_2D, null);
      framebuffer = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    },
    /** Its pixels now, as RGBA floats (a synchronous read-back: it waits for the GPU). */
    read() {
      const out = new Float32Array(target.width * target.height * 4);
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.readPixels(0, 0, target.width, target.height, gl.RGBA, gl.FLOAT, out);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      return out;
    },
    /**
     * Its pixels as drawn so far, without waiting for the GPU: a read into a pixel-pack buffer and
     * a fence polled from timers (as three.js readRenderTargetPixelsAsync does). Rejects with a
     * ContextLostError if the context is lost before the fence signals.
     */
    readAsync() {
      const out = new Float32Array(target.width * target.height * 4);
      const buffer = gl.createBuffer();
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
      gl.bufferData(gl.PIXEL_PACK_BUFFER, out.byteLength, gl.STREAM_READ);
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.readPixels(0, 0, target.width, target.height, gl.RGBA, gl.FLOAT, 0);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
      const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
      // The fence and the buffer belong to this context's generation: once it was lost they are
      // gone, even after a restore (polling them then would be an error of the new context).
      let gone = false;
      const onLost = () => { gone = true; };
      gl.canvas.addEventListener('webglcontextlost', onLost);
      return new Promise((resolve, reject) => {
        const probe = () => {
          const status = gone || gl.isContextLost() ? gl.WAIT_FAILED : gl.clientWaitSync(sync, 0, 0);
          if (status === gl.TIMEOUT_EXPIRED) {
            setTimeout(probe, 4);
            return;
          }
          gl.canvas.removeEventListener('webglcontextlost', onLost);
          if (status === gl.WAIT_FAILED) {
            reject(new ContextLostError(t('lostDuringReadBack')));
            return;
          }
          gl.deleteSync(sync);
          gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
          gl.getBufferSubData(gl.PIXEL_PACK_BUFFER, 0, out);
          gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
          gl.deleteBuffer(buffer);
          resolve(out);
        };
        setTimeout(probe, 0);
      });
    },
    dispose() {
      if (framebuffer) gl.deleteFramebuffer(framebuffer);
      if (texture) gl.deleteTexture(texture);
      framebuffer = null;
      texture = null;
    },
  };
  return target;
}
