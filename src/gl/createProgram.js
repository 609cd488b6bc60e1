// A WebGL2 program for one full-screen triangle, with setters for its uniforms found by
// introspection: a panel whose picture is analytic needs no scene graph, no buffers and no
// three.js (the triangle's corners come from gl_VertexID).

/** The vertex shader of a full-screen triangle: vUv runs 0..1 across the canvas. */
export const TRIANGLE_VERTEX_GLSL = `#version 300 es
out vec2 vUv;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  vUv = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}`;

/** A shader did not compile or link; the message holds the driver's log with the source lines it names. */
export class ShaderError extends Error {}

/** The driver's log, each "ERROR: 0:LINE:" followed by that line of the source. */
function explain(log, source) {
  const lines = source.split('\n');
  return log.trim().split('\n').map((entry) => {
    const line = /^\s*ERROR:\s*\d+:(\d+):/.exec(entry)?.[1];
    return line && lines[line - 1] !== undefined ? `${entry}\n    ${line}: ${lines[line - 1].trim()}` : entry;
  }).join('\n');
}

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
    const log = explain(gl.getShaderInfoLog(shader) ?? '', source);
    gl.deleteShader(shader);
    throw new ShaderError(`The ${type === gl.VERTEX_SHADER ? 'vertex' : 'fragment'} shader did not compile:\n${log}`);
  }
  return shader;
}

/** Floats of a uniform value: a number, a boolean, an array, a typed array, {r,g,b} or {x,y,z,w}. */
export function uniformFloats(value, count) {
  if (typeof value === 'number' || typeof value === 'boolean') return [Number(value)];
  if (Array.isArray(value)) return value.flat();
  if (ArrayBuffer.isView(value)) return value;
  if (value && 'r' in value) return [value.r, value.g, value.b];
  if (value && 'x' in value) return [value.x, value.y, value.z ?? 0, value.w ?? 0].slice(0, count);
  throw new TypeError(`A uniform value must be a number, an array or a vector, not ${String(value)}.`);
}

/** Per GL uniform type: how many components, and whether it is set as int. */
function typeInfo(gl, type) {
  const table = {
    [gl.FLOAT]: [1, false], [gl.FLOAT_VEC2]: [2, false], [gl.FLOAT_VEC3]: [3, false], [gl.FLOAT_VEC4]: [4, false],
    [gl.INT]: [1, true], [gl.INT_VEC2]: [2, true], [gl.INT_VEC3]: [3, true], [gl.INT_VEC4]: [4, true],
    [gl.BOOL]: [1, true], [gl.BOOL_VEC2]: [2, true], [gl.BOOL_VEC3]: [3, true], [gl.BOOL_VEC4]: [4, true],
    [gl.SAMPLER_2D]: [1, true], // its value is a texture unit; the caller binds the texture there
  };
  return table[type] ?? null;
}

/**
 * Compiles and links `fragment` (GLSL ES 3.00 without its #version line) with the full-screen
 * triangle. Returns { program, setUniforms(uniforms), draw(), dispose() }; uniforms are
 * { name: { value } } as three.js takes them, so panels keep one shape for both kinds of scene.
 */
export function createProgram(gl, fragment) {
  const fragmentSource = `#version 300 es\n${fragment}`;
  const vertexShader = compile(gl, gl.VERTEX_SHADER, TRIANGLE_VERTEX_GLSL);
  const fragmentShader = compile(gl, gl.FRAGMENT_SHADER, fragmentSource);
  const program = gl.createProgram();
  gl.attachShader(program, vertexShader);
  gl.attachShader(program, fragmentShader);
  gl.linkProgram(program);
  gl.deleteShader(vertexShader);
  gl.deleteShader(fragmentShader);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS) && !gl.isContextLost()) {
    const log = gl.getProgramInfoLog(program);
    gl.deleteProgram(program);
    throw new ShaderError(`The shader program did not link:\n${log}`);
  }
  const setters = new Map();
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) ?? 0;
  for (let i = 0; i < count; i += 1) {
    const info = gl.getActiveUniform(program, i);
    const kind = typeInfo(gl, info.type);
    if (!kind) throw new ShaderError(`The uniform ${info.name} has a type this view does not set (only float, int and bool vectors and sampler2D).`);
    const [size, isInt] = kind;
    const location = gl.getUniformLocation(program, info.name);
    const name = info.name.replace(/\[0\]$/, '');
    const method = `uniform${size}${isInt ? 'i' : 'f'}v`;
    setters.set(name, (value) => {
      const floats = uniformFloats(value, size);
      gl[method](location, isInt ? Int32Array.from(floats, Math.round) : floats);
    });
  }
  const vao = gl.createVertexArray(); // WebGL2 draws with no attributes from an empty VAO
  return {
    program,
    /** Sets every uniform the program uses from { name: { value } } (the others are ignored). */
    setUniforms(uniforms) {
      gl.useProgram(program);
      for (const [name, set] of setters) {
        const uniform = uniforms[name];
        if (uniform) set(uniform.value);
      }
    },
    draw() {
      gl.useProgram(program);
      gl.bindVertexArray(vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.bindVertexArray(null);
    },
    dispose() {
      gl.deleteVertexArray(vao);
      gl.deleteProgram(program);
    },
  };
}
