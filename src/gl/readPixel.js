// Reads one pixel of the default framebuffer right after a draw (the drawing buffer is not
// preserved, so the read must follow the draw in the same task). x, y are CSS pixels from the
// canvas's top-left; WebGL counts rows from the bottom.
export function readPixel(renderer, x, y, cssHeight) {
  const gl = renderer.getContext();
  const ratio = renderer.getPixelRatio();
  const out = new Uint8Array(4);
  gl.readPixels(Math.floor(x * ratio), Math.floor((cssHeight - y) * ratio), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
  return [...out];
}
