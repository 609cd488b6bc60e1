// Shared harness of the GPU twin tests: runs fragment shaders over a grid of inputs in raw WebGL2
// and reads the results back from an RGBA32F target. Each input texture is RGBA32F, width × height,
// one grid row per texel (texelFetch at gl_FragCoord); each run is a fragment shader (compiled once
// per source) with optional uniforms (int or float, by the shader's declared type).

/**
 * readBack(page, { width, height, textures: { samplerName: number[] (4 per texel) }, runs: [{
 * fragment, uniforms }] }) → one array of width·height·4 floats per run.
 */
export function readBack(page, { width, height, textures, runs }) {
  return page.evaluate(({ width, height, textures, runs }) => {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');
    const inputs = Object.entries(textures).map(([name, values]) => {
      const data = new Float32Array(width * height * 4);
      data.set(values);
      const tex = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, data);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      return { name, tex };
    });
    const target = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, target);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, gl.createFramebuffer());
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
    const vs = '#version 300 es\nvoid main(){vec2 p=vec2(gl_VertexID&1,gl_VertexID>>1)*4.0-1.0;gl_Position=vec4(p,0,1);}';
    const programs = new Map();
    const programOf = (fragment) => {
      if (programs.has(fragment)) return programs.get(fragment);
      const prog = gl.createProgram();
      for (const [type, src] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fragment]]) {
        const s = gl.createShader(type);
        gl.shaderSource(s, src);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
        gl.attachShader(prog, s);
      }
      gl.linkProgram(prog);
      if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(prog));
      const types = {};
      for (let k = 0; k < gl.getProgramParameter(prog, gl.ACTIVE_UNIFORMS); k += 1) {
        const info = gl.getActiveUniform(prog, k);
        types[info.name] = info.type;
      }
      programs.set(fragment, { prog, types });
      return programs.get(fragment);
    };
    gl.viewport(0, 0, width, height);
    return runs.map(({ fragment, uniforms = {} }) => {
      const { prog, types } = programOf(fragment);
      gl.useProgram(prog);
      inputs.forEach(({ name, tex }, unit) => {
        gl.activeTexture(gl.TEXTURE0 + unit);
        gl.bindTexture(gl.TEXTURE_2D, tex);
        gl.uniform1i(gl.getUniformLocation(prog, name), unit);
      });
      for (const [name, value] of Object.entries(uniforms)) {
        if (!(name in types)) throw new Error(`uniform ${name} is not active in the shader`);
        const at = gl.getUniformLocation(prog, name);
        if (types[name] === gl.INT) gl.uniform1i(at, value);
        else gl.uniform1f(at, value);
      }
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      const out = new Float32Array(width * height * 4);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, out);
      return Array.from(out);
    });
  }, { width, height, textures, runs });
}
