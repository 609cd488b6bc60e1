// Makes (and drops) one WebGL2 context off the page's thread; see warmGpu.js.
let ok = false;
try {
  const gl = new OffscreenCanvas(1, 1).getContext('webgl2');
  ok = Boolean(gl);
  gl?.getExtension('WEBGL_lose_context')?.loseContext();
} catch {
  ok = false;
}
postMessage(ok);
close();
