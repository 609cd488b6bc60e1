// The page's one shader plumbing: every WebGL2 program is a fragment shader of the caller's with
// the one full-screen vertex shader below, compiled and linked here, drawn as one triangle, and a
// refusal is a ShaderError (shaderError.js) carrying the driver's log and the stage that failed.
import { ShaderError } from './shaderError.js';

/**
 * The full-screen vertex shader: vertices 0, 1, 2 at (-1,-1), (3,-1), (-1,3) in clip space, one
 * triangle whose inside holds the whole viewport (clipping trims the rest). One triangle rather than
 * a quad: no diagonal where two triangles shade the same 2×2 pixel blocks twice, and no buffers
 * (gl_VertexID, GLSL ES 3.00 §7.1). vUv runs 0..1 across the viewport; a fragment that does not
 * read it need not declare it (GLSL ES 3.00: "declaring superfluous vertex shader outputs is
 * permissible").
 */
export const FULL_SCREEN_VERTEX = `#version 300 es
out vec2 vUv;
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
  vUv = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}`;

/** The shaders of each program, for checkProgram's statuses and logs. */
const shadersOf = new WeakMap();

/**
 * Compiles `fragment` (GLSL ES 3.00 source, #version line included) with FULL_SCREEN_VERTEX and
 * links them; returns the WebGLProgram or throws ShaderError (deleting the program). label names
 * the program in the error's message. check: false returns the program unchecked, so that many
 * programs can be compiled before any status is asked for (a driver compiling in parallel is not
 * made to wait, KHR_parallel_shader_compile); then call checkProgram on each before using it.
 * @param {WebGL2RenderingContext} gl
 * @param {string} fragment
 * @param {{ label?: string, check?: boolean }} [options]
 */
export function compileProgram(gl, fragment, { label = '', check = true } = {}) {
  const program = gl.createProgram();
  const shaders = [
    ['vertex', gl.VERTEX_SHADER, FULL_SCREEN_VERTEX], ['fragment', gl.FRAGMENT_SHADER, fragment],
  ].map(([stage, type, source]) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    gl.attachShader(program, shader);
    return { stage, shader, source };
  });
  gl.linkProgram(program);
  // Only flagged: an attached shader lives (and its status and log can be read) until its
  // program is deleted (OpenGL ES 3.0 §2.11.1, glDeleteShader).
  for (const { shader } of shaders) gl.deleteShader(shader);
  shadersOf.set(program, shaders);
  if (check) {
    try {
      checkProgram(gl, program, { label });
    } catch (error) {
      gl.deleteProgram(program);
      throw error;
    }
  }
  return program;
}

/**
 * Throws ShaderError if a shader of `program` (from compileProgram) did not compile (the vertex
 * stage is reported first) or the program did not link. On a lost context every status reads as
 * failed, so nothing is thrown: the loss is for the context's owner to handle.
 * @param {WebGL2RenderingContext} gl
 * @param {WebGLProgram} program
 * @param {{ label?: string }} [options]
 */
export function checkProgram(gl, program, { label = '' } = {}) {
  if (gl.isContextLost()) return;
  for (const { stage, shader, source } of shadersOf.get(program) ?? []) {
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new ShaderError({ stage, log: gl.getShaderInfoLog(shader), source, label });
    }
  }
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new ShaderError({ stage: 'link', log: gl.getProgramInfoLog(program), label });
  }
}

/**
 * The full-screen triangle of a context: draw() draws it with whatever program is in use (into
 * the bound framebuffer, over the viewport). Its own empty vertex array, so attribute arrays
 * another user of the context left enabled (three.js, say) are never read.
 * @param {WebGL2RenderingContext} gl
 */
export function createFullScreenTriangle(gl) {
  const vao = gl.createVertexArray();
  return {
    draw() {
      gl.bindVertexArray(vao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      gl.bindVertexArray(null);
    },
    dispose() {
      gl.deleteVertexArray(vao);
    },
  };
}
