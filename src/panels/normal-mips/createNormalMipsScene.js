// The receding plane of the normal-mips panel: one fragment source (normal-mips.frag.glsl)
// compiled into three programs, one per pass, drawn into float targets: the technique's picture,
// the progressive ground truth (a running mean over frames, stopped at a sample cap) and the
// composited display. Plain WebGL2: every technique's chain is uploaded level by level from
// uploadLevels() (createMipTexture), so the shader samples exactly what the technique stored.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { cappedPixelRatio } from '../../gl/cappedPixelRatio.js';
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { createContext } from '../../gl/createContext.js';
import { ContextLostError, createFloatTarget } from '../../gl/createFloatTarget.js';
import { currentOwner } from '../../gl/faultOwner.js';
import { createMipTexture, maxAnisotropy, setAnisotropy } from '../../gl/createMipTexture.js';
import { createProgram } from '../../gl/createProgram.js';
import { assembleShader } from '../../gl/shaderChunks.js';
import { onDemand } from '../../gl/onDemand.js';
import { createRunGate } from '../shared/createRunGate.js';
import fragment from './normal-mips.frag.glsl?raw';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { uploadLevels } from '../../normals/uploadLevels.js';
import { bandedRmse } from '../../normals/bandedRmse.js';
import { meanBrightnessChange } from '../../normals/shimmer.js';

const t = messages('normal-mips', english);

// Small batches keep each frame short on slow (software) GPUs while the truth accumulates.
export const SAMPLES_PER_FRAME = 8;

// The texture unit of each sampler of the shader.
const UNITS = { uTexA: 0, uTexB: 1, uPrev: 2, uTech: 3, uTruth: 4 };

// u8 decodes in the shader as min + (max − min)·c; float types as they are.
function decodeOf(upload) {
  const unorm = upload.type === 'u8';
  const scale = [0, 1, 2, 3].map((k) => (unorm && upload.ranges[k] ? upload.ranges[k].max - upload.ranges[k].min : 1));
  const offset = [0, 1, 2, 3].map((k) => (unorm && upload.ranges[k] ? upload.ranges[k].min : 0));
  return { scale, offset };
}

function startContext(canvas) {
  const context = createContext(canvas);
  enableExtensions(context.gl);
  if (!context.gl.getExtension('EXT_color_buffer_float')) {
    context.dispose();
    throw new WebGL2Unavailable(t('noFloatTargets'));
  }
  return context;
}

/** Extensions are enabled per context, so again after a restore. */
function enableExtensions(gl) {
  gl.getExtension('EXT_color_buffer_float');
  gl.getExtension('OES_texture_float_linear');
  gl.getExtension('EXT_texture_filter_anisotropic');
}

/**
 * The scene on a canvas. uniforms: the shader's first values; onFrame: after each frame drawn;
 * onConverged(errors): the errors of every technique against a converged truth; onContextLost:
 * the context went away (a running measurement is stale); maxPixels: the drawing buffer's cap.
 */
export function createNormalMipsScene(canvas, {
  uniforms: initial, onFrame, onConverged, onContextLost, maxPixels = 120_000,
}) {
  const context = startContext(canvas);
  const { gl } = context;
  const source = assembleShader(fragment);
  const u = {
    uResolution: { value: [1, 1] }, uDebug: { value: 0 },
    uScaleA: { value: [1, 1, 1, 1] }, uOffsetA: { value: [0, 0, 0, 0] },
    uScaleB: { value: [1, 1, 1, 1] }, uOffsetB: { value: [0, 0, 0, 0] },
    uTechnique: { value: 0 }, uChannels: { value: 3 },
    uSamples: { value: SAMPLES_PER_FRAME }, uFrame: { value: 0 }, uBlend: { value: 1 }, uJitter: { value: [0, 0] },
  };
  for (const [k, v] of Object.entries(initial)) u[k] = { value: v };
  const samplers = Object.fromEntries(Object.entries(UNITS).map(([name, unit]) => [name, { value: unit }]));
  let programs = [];
  let dummy = null; // a 1×1 texture on the units a pass does not read
  const rtTech = createFloatTarget(gl);
  const rtMeasure = createFloatTarget(gl); // the error measurement draws here, so the picture's target is left alone
  const rtTruth = [createFloatTarget(gl), createFloatTarget(gl)];
  let uploads = {}; // technique → packed chains, kept to upload again after a lost context
  let textures = {}; // technique → [{ tex, scale, offset }]
  const state = {
    technique: 'naive', channels: 3, samples: 0, cap: 256, truthOn: true, onScreen: false, errors: null, measuring: false, frame: 0,
    anisotropy: 1,
  };
  let cur = 0;
  const bound = { uTexA: null, uTexB: null };

  function build() {
    programs = [0, 1, 2].map((pass) => createProgram(gl, `#define PASS ${pass}\n${source}`));
    dummy = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, dummy);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    gl.bindTexture(gl.TEXTURE_2D, null);
    const [w, h] = u.uResolution.value;
    for (const rt of [rtTech, rtMeasure, ...rtTruth]) rt.setSize(w, h);
  }
  build();

  function bindTechnique(technique) {
    const [a, b] = textures[technique] ?? [];
    u.uTechnique.value = TECHNIQUES.indexOf(technique);
    bound.uTexA = a?.tex ?? null;
    u.uScaleA.value = a?.scale ?? [1, 1, 1, 1];
    u.uOffsetA.value = a?.offset ?? [0, 0, 0, 0];
    bound.uTexB = b?.tex ?? null;
    u.uScaleB.value = b?.scale ?? [1, 1, 1, 1];
    u.uOffsetB.value = b?.offset ?? [0, 0, 0, 0];
  }

  // Only the display pass reads the targets; the others must not bind the target they draw into.
  function pass(index, target) {
    const textureOf = {
      uTexA: index === 0 ? bound.uTexA : null,
      uTexB: index === 0 ? bound.uTexB : null,
      uPrev: index === 1 ? rtTruth[cur].texture : null,
      uTech: index === 2 ? rtTech.texture : null,
      uTruth: index === 2 ? rtTruth[cur].texture : null,
    };
    for (const [name, unit] of Object.entries(UNITS)) {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, textureOf[name] ?? dummy);
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, target?.framebuffer ?? null);
    gl.viewport(0, 0, target ? target.width : gl.drawingBufferWidth, target ? target.height : gl.drawingBufferHeight);
    const program = programs[index];
    program.setUniforms(samplers);
    program.setUniforms(u);
    program.draw();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  }

  // The error of every technique against the converged truth. Each technique is drawn into its own
  // target and read back asynchronously (a pixel-pack buffer and a fence), so the page never waits
  // for the GPU: on a slow GPU six synchronous read-backs would freeze it for seconds. The previous
  // errors stay in state.errors until the new set is complete; a restart, a newer measurement, a
  // lost context or dispose makes a running one stale (its gate).
  const measureGate = createRunGate();
  const owner = currentOwner(); // the panel an error of a measurement, which runs outside its code, belongs to
  let measured = []; // resolvers of whenMeasured()
  let disposed = false;

  function startMeasure() {
    const run = measureGate.begin();
    state.measuring = true;
    runMeasure(run).catch((error) => {
      if (!run.live) return; // a read-back of a context already given up
      stopMeasure();
      // Lost before its event arrived: the restore starts the truth, and the measurement, again.
      if (error instanceof ContextLostError) return;
      if (!owner) throw error;
      owner.fail(error); // said in the panel (panelFaults.js)
    });
  }

  async function runMeasure(run) {
    const truth = await rtTruth[cur].readAsync();
    if (!run.live) return;
    const errors = {};
    for (const technique of TECHNIQUES) {
      bindTechnique(technique);
      pass(0, rtMeasure);
      bindTechnique(state.technique);
      const image = await rtMeasure.readAsync();
      if (!run.live) return;
      errors[technique] = bandedRmse(image, truth, { bands: u.uMaxLevel.value + 1 });
    }
    state.errors = errors;
    stopMeasure();
    onConverged?.(errors);
  }

  /** Ends the running measurement (its result, if any, is dropped) and wakes whenMeasured(). */
  function stopMeasure() {
    measureGate.cancel('The measurement ended');
    state.measuring = false;
    const waiting = measured;
    measured = [];
    waiting.forEach((resolve) => resolve());
  }

  function draw() {
    if (gl.isContextLost() || !Object.keys(textures).length) return; // nothing to show until the first chains arrive
    u.uDebug.value = 0;
    bindTechnique(state.technique);
    pass(0, rtTech);
    const accumulating = state.truthOn && state.onScreen && state.samples < state.cap;
    if (accumulating) {
      const next = 1 - cur;
      u.uFrame.value = state.frame++;
      u.uBlend.value = SAMPLES_PER_FRAME / (state.samples + SAMPLES_PER_FRAME);
      pass(1, rtTruth[next]); // reads rtTruth[cur]
      cur = next;
      state.samples += SAMPLES_PER_FRAME;
      if (state.samples >= state.cap) startMeasure();
    }
    pass(2, null);
    onFrame?.();
    if (accumulating && state.samples < state.cap) frames.request();
  }
  const frames = onDemand(draw);

  // The ground truth accumulates only while the canvas is on screen: a panel mounted ahead of the
  // reader (or scrolled past) spends nothing on it, and picks up where it stopped when seen.
  const visibility = new IntersectionObserver(([record]) => {
    state.onScreen = record.isIntersecting;
    if (state.onScreen && state.truthOn && state.samples < state.cap) frames.request();
  });
  visibility.observe(canvas);

  // The drawing buffer follows the canvas size, but changes under 10 % (a scrollbar coming and
  // going as the table fills) are left to CSS scaling: a resize restarts the ground truth.
  const resizeObserver = new ResizeObserver(() => {
    const rect = canvas.getBoundingClientRect();
    const width = Math.max(1, Math.round(rect.width));
    const height = Math.max(1, Math.round(rect.height));
    const ratio = cappedPixelRatio(width, height, window.devicePixelRatio, 2, maxPixels);
    const [w0, h0] = u.uResolution.value;
    if (Math.abs(width * ratio - w0) < 0.1 * w0 && Math.abs(height * ratio - h0) < 0.1 * h0) return;
    canvas.width = Math.max(1, Math.floor(width * ratio));
    canvas.height = Math.max(1, Math.floor(height * ratio));
    u.uResolution.value = [canvas.width, canvas.height];
    for (const rt of [rtTech, rtMeasure, ...rtTruth]) rt.setSize(canvas.width, canvas.height);
    restartTruth();
  });
  resizeObserver.observe(canvas);

  function restartTruth() {
    state.samples = 0;
    state.frame = 0;
    state.errors = null;
    if (state.measuring) stopMeasure();
    frames.request();
  }

  function uploadTextures() {
    disposeTextures();
    for (const [technique, packed] of Object.entries(uploads)) {
      textures[technique] = packed.map((upload) => ({ tex: createMipTexture(gl, upload, state.anisotropy), ...decodeOf(upload) }));
    }
  }

  function disposeTextures() {
    for (const list of Object.values(textures)) for (const { tex } of list) gl.deleteTexture(tex);
    textures = {};
  }

  // A lost context (a GPU reset, too many tabs) comes back if the page asks for it: the programs,
  // targets and textures are made again from what the scene kept, and the truth starts over.
  const onLost = (event) => {
    event.preventDefault();
    frames.cancel();
    if (state.measuring) stopMeasure();
    onContextLost?.();
  };
  const onRestored = () => {
    enableExtensions(gl);
    textures = {}; // the old objects went with the context
    build();
    uploadTextures();
    restartTruth();
  };
  canvas.addEventListener('webglcontextlost', onLost);
  canvas.addEventListener('webglcontextrestored', onRestored);

  return {
    gl,
    /** 32-bit float textures are filtered only with OES_texture_float_linear. */
    floatLinear: Boolean(gl.getExtension('OES_texture_float_linear')),
    /** The largest anisotropic filtering level this GPU offers (1 without the extension). */
    maxAnisotropy: maxAnisotropy(gl),
    uniforms: u,
    state,
    frames,
    /**
     * Uploads every technique's chain (from buildAllChains) and restarts nothing else; uploads,
     * when given, are the chains already packed by uploadLevels (as buildChainsFor returns them).
     */
    setChains(chains, packed = {}) {
      uploads = Object.fromEntries(TECHNIQUES.map((technique) => [technique, packed[technique] ?? uploadLevels(chains[technique])]));
      uploadTextures();
      frames.request();
    },
    /** Sets uniforms; truthChanged restarts the ground truth (and the error table). */
    set({ technique, channels, cap, truthOn, anisotropy, ...values }, truthChanged) {
      if (technique !== undefined) state.technique = technique;
      if (anisotropy !== undefined && anisotropy !== state.anisotropy) {
        state.anisotropy = anisotropy;
        u.uAniso.value = anisotropy;
        for (const list of Object.values(textures)) for (const { tex } of list) setAnisotropy(gl, tex, anisotropy);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
      if (channels !== undefined) u.uChannels.value = channels;
      if (cap !== undefined) state.cap = cap;
      if (truthOn !== undefined) state.truthOn = truthOn;
      for (const [k, v] of Object.entries(values)) u[k].value = v;
      if (truthChanged) restartTruth();
      else frames.request();
    },
    /** The stored chains or the forced level changed but not the truth: re-measure against the converged truth. */
    refreshErrors() {
      if (state.errors) startMeasure();
    },
    /** Resolves when no error measurement is running (at once if none is). */
    whenMeasured() {
      return state.measuring ? new Promise((resolve) => { measured.push(resolve); }) : Promise.resolve();
    },
    /** Test probe: the decoded texels of `level` of a technique's texture, read at pixel-aligned centres. */
    debugLevel(technique, level, textureIndex = 0) {
      const forced = u.uForcedLevel.value;
      bindTechnique(technique);
      u.uForcedLevel.value = level;
      u.uDebug.value = textureIndex + 1;
      pass(0, rtTech);
      const data = rtTech.read();
      u.uDebug.value = 0;
      u.uForcedLevel.value = forced;
      frames.request();
      return { data, width: rtTech.width, height: rtTech.height };
    },
    /**
     * Shimmer meter: mean |Δ brightness| per pixel of each technique's picture under sub-pixel
     * camera moves. Asynchronous read-backs, as for the errors; resolves null if disposed or the
     * context was lost meanwhile, and rejects with the signal's reason once it is aborted.
     * @param {{ signal?: AbortSignal }} [options]
     */
    async measureShimmer({ signal } = {}) {
      const offsets = [[0.5, 0], [0, 0.5], [0.5, 0.5], [0.25, 0.75]];
      const drawMoved = (technique, jitter) => {
        bindTechnique(technique);
        u.uJitter.value = jitter;
        pass(0, rtMeasure);
        u.uJitter.value = [0, 0]; // the picture itself is never jittered
        bindTechnique(state.technique);
        return rtMeasure.readAsync();
      };
      const result = {};
      try {
        for (const technique of TECHNIQUES) {
          signal?.throwIfAborted();
          const still = await drawMoved(technique, [0, 0]);
          let sum = 0;
          for (const offset of offsets) {
            const moved = await drawMoved(technique, offset);
            if (disposed) return null;
            signal?.throwIfAborted(); // a newer measurement or a change of settings: stop drawing
            sum += meanBrightnessChange(still, moved);
          }
          result[technique] = sum / offsets.length;
        }
      } catch (error) {
        if (disposed || error instanceof ContextLostError) return null; // the context went away under a read-back
        throw error;
      }
      return result;
    },
    /** The current technique's linear picture (RGB, λ in alpha) as drawn now. */
    readTechnique() {
      bindTechnique(state.technique);
      pass(0, rtTech);
      return rtTech.read();
    },
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      frames.cancel();
      disposed = true;
      if (state.measuring) stopMeasure();
      measureGate.dispose();
      resizeObserver.disconnect();
      visibility.disconnect();
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
      disposeTextures();
      gl.deleteTexture(dummy);
      for (const rt of [rtTech, rtMeasure, ...rtTruth]) rt.dispose();
      programs.forEach((program) => program.dispose());
      context.dispose();
    },
  };
}
