// A WebGL2 program for one full-screen triangle (compileProgram.js), with setters for its uniforms
// found by introspection: a panel whose picture is analytic needs no scene graph, no buffers and no
// three.js.
import { compileProgram, createFullScreenTriangle } from './compileProgram.js';

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
 * triangle; throws ShaderError (shaderError.js) when the driver refuses it. Returns { program,
 * setUniforms(uniforms), draw(), dispose() }; uniforms are { name: { value } } as three.js takes
 * them, so panels keep one shape for both kinds of scene.
 */
export function createProgram(gl, fragment) {
  const program = compileProgram(gl, `#version 300 es\n${fragment}`);
  const setters = new Map();
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS) ?? 0;
  for (let i = 0; i < count; i += 1) {
    const info = gl.getActiveUniform(program, i);
    const kind = typeInfo(gl, info.type);
    if (!kind) {
      throw new TypeError(`The uniform ${info.name} has a type this view does not set (only float, int and bool vectors and sampler2D).`);
    }
    const [size, isInt] = kind;
    const location = gl.getUniformLocation(program, info.name);
    const name = info.name.replace(/\[0\]$/, '');
    const method = `uniform${size}${isInt ? 'i' : 'f'}v`;
    setters.set(name, (value) => {
      const floats = uniformFloats(value, size);
      gl[method](location, isInt ? Int32Array.from(floats, Math.round) : floats);
    });
  }
  const triangle = createFullScreenTriangle(gl);
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
      triangle.draw();
    },
    dispose() {
      triangle.dispose();
      gl.deleteProgram(program);
    },
  };
}
