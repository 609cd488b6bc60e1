// Every Fresnel method of shaders/fresnelMethods.glsl evaluated on this GPU: one fragment per
// sample renders into an RGBA32F target (EXT_color_buffer_float) and readPixels(FLOAT) brings
// the results back bit for bit, NaN and ±Infinity included; in-shader isnan() cannot be trusted
// (GLSL ES 3.00 need not support NaN: "NaNs may not be supported by the implementation, in which
// case isnan returns false", Khronos isnan reference page). Raw WebGL2 on a context the caller
// owns: a panel's read-back GPU (src/panels/shared/createReadBackGpu.js) makes one evaluator on its
// own context, the speed-accuracy measurement and the benchmark one on theirs.
// GL state touched here (framebuffers, program, vertex array, viewport, texture units 0–1,
// pixel-store and capability flags) is restored after each call; three.js users may still call
// renderer.resetState() afterwards to be safe.
import { compileProgram, createFullScreenTriangle } from './compileProgram.js';
import { resolveIncludes } from './resolveIncludes.js';
import { shaderChunks } from './shaderChunks.js';
import { GPU_PRECISIONS, methodIndex } from './methodIndex.js';
import { f82Coefficients, methodById } from '../methods/methods.js';
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

export class GpuFloatUnavailable extends Error {}

const MAX_WIDTH = 1024;

function checkPrecision(precision) {
  if (!GPU_PRECISIONS.includes(precision)) throw new RangeError(`precision must be highp or mediump, got ${String(precision)}`);
}

/**
 * The fragment shader evaluating one method: inputs are read at full float32 (highp sampler) and
 * converted to the default precision at the call to fm_evaluate, as a uniform or varying would be.
 */
export function methodFragmentSource(methodId, precision, chunks = shaderChunks) {
  checkPrecision(precision);
  return resolveIncludes(`#version 300 es
precision ${precision} float;
precision highp int;
precision highp sampler2D;
#include <fresnelMethods>
uniform sampler2D uInputs;
uniform sampler2D uExtra;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  outColor = vec4(fm_evaluate(${methodIndex(methodId)}, texelFetch(uInputs, p, 0), texelFetch(uExtra, p, 0)), 0.0, 0.0, 1.0);
}`, chunks);
}

// 1 + 2^-f in the tested precision for f = 1..30: the largest f that does not round to 1 is the
// fraction width (23 for float32, 10 for float16). Inputs come from a texture so nothing folds.
function probeFragmentSource(precision) {
  return `#version 300 es
precision ${precision} float;
precision highp sampler2D;
uniform sampler2D uInputs;
uniform sampler2D uExtra;
out vec4 outColor;
void main() {
  vec4 v = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0);
  float one = v.x;
  float tiny = v.y;
  float sum = one + tiny;
  outColor = vec4(sum, 0.0, 0.0, 1.0);
}`;
}

const STORE = ['UNPACK_FLIP_Y_WEBGL', 'UNPACK_PREMULTIPLY_ALPHA_WEBGL', 'UNPACK_ALIGNMENT', 'UNPACK_ROW_LENGTH',
  'UNPACK_SKIP_ROWS', 'UNPACK_SKIP_PIXELS', 'PACK_ALIGNMENT', 'PACK_ROW_LENGTH', 'PACK_SKIP_ROWS', 'PACK_SKIP_PIXELS'];
const CAPS = ['BLEND', 'DEPTH_TEST', 'SCISSOR_TEST', 'CULL_FACE', 'STENCIL_TEST', 'RASTERIZER_DISCARD', 'DITHER'];

// Saves what a pass changes, sets the neutral state it needs, and returns a restore function.
function enterPass(gl) {
  const saved = {
    draw: gl.getParameter(gl.DRAW_FRAMEBUFFER_BINDING),
    read: gl.getParameter(gl.READ_FRAMEBUFFER_BINDING),
    program: gl.getParameter(gl.CURRENT_PROGRAM),
    vao: gl.getParameter(gl.VERTEX_ARRAY_BINDING),
    viewport: gl.getParameter(gl.VIEWPORT),
    mask: gl.getParameter(gl.COLOR_WRITEMASK),
    active: gl.getParameter(gl.ACTIVE_TEXTURE),
    unpackBuffer: gl.getParameter(gl.PIXEL_UNPACK_BUFFER_BINDING),
    packBuffer: gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING),
    store: STORE.map((name) => gl.getParameter(gl[name])),
    caps: CAPS.map((name) => gl.isEnabled(gl[name])),
    units: [0, 1].map((u) => {
      gl.activeTexture(gl.TEXTURE0 + u);
      return gl.getParameter(gl.TEXTURE_BINDING_2D);
    }),
  };
  STORE.forEach((name) => gl.pixelStorei(gl[name], name.endsWith('ALIGNMENT') ? 4 : 0));
  CAPS.forEach((name) => gl.disable(gl[name]));
  gl.colorMask(true, true, true, true);
  gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, null);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  return () => {
    saved.units.forEach((tex, u) => {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, tex);
    });
    gl.activeTexture(saved.active);
    STORE.forEach((name, i) => gl.pixelStorei(gl[name], saved.store[i]));
    CAPS.forEach((name, i) => (saved.caps[i] ? gl.enable(gl[name]) : gl.disable(gl[name])));
    gl.colorMask(...saved.mask);
    gl.bindBuffer(gl.PIXEL_UNPACK_BUFFER, saved.unpackBuffer);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, saved.packBuffer);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, saved.draw);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, saved.read);
    gl.useProgram(saved.program);
    gl.bindVertexArray(saved.vao);
    gl.viewport(...saved.viewport);
  };
}

function floatTexture(gl, unit, texture, width, height, data) {
  gl.activeTexture(gl.TEXTURE0 + unit);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST); // RGBA32F is not filterable
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, data);
}

/** 4 floats per sample: as given, one vec4 for all samples, F82's b computed per sample, or zeros. */
function extraFor(methodId, inputs, extra, count) {
  if (extra && extra.length === count * 4) return extra;
  const out = new Float32Array(count * 4);
  if (extra && extra.length === 4) {
    for (let i = 0; i < count; i += 1) out.set(extra, i * 4);
  } else if (extra) {
    throw new RangeError(`extra must hold 4 floats per sample (${count * 4}) or 4 in all, got ${extra.length}`);
  } else if (methodId === 'conductor-f82') {
    for (let i = 0; i < count; i += 1) out[i * 4] = f82Coefficients(inputs[i * 4 + 1], inputs[i * 4 + 2], inputs[i * 4 + 3]).b;
  }
  return out;
}

/**
 * The evaluator of one WebGL2 context. Programs are compiled once per (method, precision) by
 * compileProgram (a refusal throws ShaderError). Throws GpuFloatUnavailable when the context
 * cannot render to RGBA32F.
 */
export function createMethodsGpu(gl) {
  if (!gl.getExtension('EXT_color_buffer_float')) {
    throw new GpuFloatUnavailable(t('noFloatTargets'));
  }
  const programs = new Map();
  const triangle = createFullScreenTriangle(gl);
  const inputsTex = gl.createTexture();
  const extraTex = gl.createTexture();
  const target = gl.createTexture();
  const framebuffer = gl.createFramebuffer();
  let disposed = false;
  let probe = null;

  function programFor(key, source) {
    if (!programs.has(key)) {
      const program = compileProgram(gl, source);
      programs.set(key, { program, inputs: gl.getUniformLocation(program, 'uInputs'), extra: gl.getUniformLocation(program, 'uExtra') });
    }
    return programs.get(key);
  }

  function run(entry, inputs, extra, count, channels = 1) {
    if (disposed) throw new Error(t('evaluatorDisposed'));
    if (gl.isContextLost()) throw new Error(t('contextLost'));
    const width = Math.min(count, MAX_WIDTH);
    const height = Math.ceil(count / width);
    if (height > gl.getParameter(gl.MAX_TEXTURE_SIZE)) throw new RangeError(t('tooManySamples', { count: String(count) }));
    const padded = (data) => {
      if (data.length === width * height * 4) return data;
      const out = new Float32Array(width * height * 4);
      out.set(data);
      return out;
    };
    const restore = enterPass(gl);
    try {
      floatTexture(gl, 0, inputsTex, width, height, padded(inputs));
      floatTexture(gl, 1, extraTex, width, height, padded(extra));
      floatTexture(gl, 0, target, width, height, null);
      gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
      if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) {
        throw new GpuFloatUnavailable(t('floatTargetIncomplete'));
      }
      gl.bindTexture(gl.TEXTURE_2D, inputsTex); // unit 0 back to the inputs (the target is attached)
      gl.useProgram(entry.program);
      gl.uniform1i(entry.inputs, 0);
      gl.uniform1i(entry.extra, 1);
      gl.viewport(0, 0, width, height);
      triangle.draw();
      const out = new Float32Array(width * height * 4);
      gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, out);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, null, 0);
      const result = new Float32Array(count * channels);
      for (let i = 0; i < count; i += 1) for (let ch = 0; ch < channels; ch += 1) result[i * channels + ch] = out[i * 4 + ch];
      return result;
    } finally {
      restore();
    }
  }

  return {
    gl,
    /**
     * evaluate({ methodId, precision: 'highp' | 'mediump', inputs, extra? }) → Float32Array, one
     * result per sample. inputs: Float32Array, 4 floats per sample: (cos θ, nI, nT, unused) for
     * dielectrics, (cos θ, n, k, f0) for conductors. extra: optional Float32Array, 4 per sample or
     * 4 for all; extra.x is F82's b (computed from n, k, f0 when omitted for conductor-f82).
     * @param {{ methodId: string, precision?: string, inputs: Float32Array, extra?: Float32Array | null }} options
     */
    evaluate({ methodId, precision = 'highp', inputs, extra }) {
      methodById(methodId);
      checkPrecision(precision);
      if (!(inputs instanceof Float32Array) || inputs.length === 0 || inputs.length % 4 !== 0) {
        throw new RangeError('inputs must be a non-empty Float32Array of 4 floats per sample');
      }
      const count = inputs.length / 4;
      const entry = programFor(`${methodId}|${precision}`, methodFragmentSource(methodId, precision));
      return run(entry, inputs, extraFor(methodId, inputs, extra, count), count);
    },
    /**
     * A fragment shader of the caller's (the shader lab's wrapper around a student's function,
     * reading uInputs and uExtra as methodFragmentSource's do) evaluated per sample: `channels`
     * floats per sample (1: red, 3: rgb). Compiled once per key (the caller keeps only its newest:
     * forget); a failure throws ShaderError (shaderError.js) with the driver's log.
     */
    evaluateSource({ key, source, inputs, extra = null, channels = 1 }) {
      if (!(inputs instanceof Float32Array) || inputs.length === 0 || inputs.length % 4 !== 0) {
        throw new RangeError('inputs must be a non-empty Float32Array of 4 floats per sample');
      }
      const count = inputs.length / 4;
      return run(programFor(`source|${key}`, source), inputs, extra ?? new Float32Array(count * 4), count, channels);
    },
    /** Frees the programs evaluateSource compiled under keys that start with `prefix`. */
    forget(prefix) {
      for (const [key, entry] of programs) {
        if (key.startsWith(`source|${prefix}`)) {
          gl.deleteProgram(entry.program);
          programs.delete(key);
        }
      }
    },
    /**
     * What mediump and highp really are, by rendering: { highpBits, mediumpBits (significand bits
     * including the hidden one: 24 for float32, 11 for float16), mediumpIsFullPrecision }.
     */
    probePrecision() {
      if (!probe) {
        const count = 30;
        const inputs = new Float32Array(count * 4);
        for (let f = 1; f <= count; f += 1) inputs.set([1, 2 ** -f, 0, 0], (f - 1) * 4);
        const bits = (precision) => {
          const sums = run(programFor(`probe|${precision}`, probeFragmentSource(precision)), inputs, new Float32Array(count * 4), count);
          let fraction = 0;
          sums.forEach((s, i) => { if (s !== 1 && fraction === i) fraction = i + 1; });
          return fraction + 1;
        };
        const highpBits = bits('highp');
        const mediumpBits = bits('mediump');
        probe = Object.freeze({ highpBits, mediumpBits, mediumpIsFullPrecision: mediumpBits >= 24 });
      }
      return probe;
    },
    get programCount() { return programs.size; },
    dispose() {
      if (disposed) return;
      disposed = true;
      for (const { program } of programs.values()) gl.deleteProgram(program);
      programs.clear();
      triangle.dispose();
      for (const t of [inputsTex, extraTex, target]) gl.deleteTexture(t);
      gl.deleteFramebuffer(framebuffer);
    },
  };
}

/**
 * What the driver claims for fragment-shader floats: { highp, mediump } each { rangeMin,
 * rangeMax, precision } (precision: fraction bits, 23 for float32, 10 for float16). Not trusted:
 * Safari/iOS has reported wrong values (webglfundamentals "WebGL Precision Issues");
 * probePrecision() measures it by rendering instead.
 */
export function gpuPrecisionInfo(gl) {
  const read = (type) => {
    const f = gl.getShaderPrecisionFormat(gl.FRAGMENT_SHADER, type);
    return f ? { rangeMin: f.rangeMin, rangeMax: f.rangeMax, precision: f.precision } : null;
  };
  return { highp: read(gl.HIGH_FLOAT), mediump: read(gl.MEDIUM_FLOAT) };
}
