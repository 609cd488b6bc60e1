// Makes (and drops) one WebGL2 context off the page's thread; see warmGpu.js.
function makeContext() {
  try {
    const gl = new OffscreenCanvas(1, 1).getContext('webgl2');
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    return Boolean(gl);
  } catch {
    return false;
  }
}
postMessage(makeContext());
close();
