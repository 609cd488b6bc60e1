// The receding plane of the normal-mips panel: one fragment program (normal-mips.frag.glsl)
// run in three passes into float targets: the technique's picture, the progressive ground truth
// (a running mean over frames, stopped at a sample cap) and the composited display. Every
// technique's chain is uploaded level by level from uploadLevels(), so the shader samples exactly
// what the technique stored (three.js uploads texture.mipmaps and sets generateMipmaps = false).
import {
  DataTexture, FloatType, HalfFloatType, LinearFilter, LinearMipmapLinearFilter, NearestFilter, NoColorSpace, RedFormat,
  RepeatWrapping, RGBAFormat, RGFormat, UnsignedByteType, Vector2, WebGLRenderTarget,
} from 'three';
import { cappedPixelRatio, createRenderer } from '../../gl/createRenderer.js';
import { onDemand } from '../../gl/onDemand.js';
import { createFullscreenPass } from '../../gl/createFullscreenPass.js';
import fragment from './normal-mips.frag.glsl?raw';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { uploadLevels } from '../../normals/uploadLevels.js';
import { bandedRmse } from '../../optics/bandedRmse.js';
import { meanBrightnessChange } from '../../optics/shimmer.js';

const FORMATS = { RGBA: RGBAFormat, RG: RGFormat, R: RedFormat };
const TYPES = { u8: UnsignedByteType, f16: HalfFloatType, f32: FloatType };
// Small batches keep each frame short on slow (software) GPUs while the truth accumulates.
export const SAMPLES_PER_FRAME = 8;

// One DataTexture per uploaded texture, every level supplied; u8 decodes as min + (max − min)·c.
// anisotropy: EXT_texture_filter_anisotropic's level (three.js sets it when the texture uploads).
function makeTexture(upload, anisotropy) {
  const [first] = upload.mipmaps;
  const tex = new DataTexture(first.data, first.width, first.height, FORMATS[upload.format], TYPES[upload.type]);
  tex.mipmaps = upload.mipmaps;
  tex.generateMipmaps = false;
  tex.minFilter = LinearMipmapLinearFilter;
  tex.magFilter = LinearFilter;
  tex.wrapS = RepeatWrapping;
  tex.wrapT = RepeatWrapping;
  tex.colorSpace = NoColorSpace;
  tex.anisotropy = anisotropy;
  tex.needsUpdate = true;
  const unorm = upload.type === 'u8';
  const scale = [0, 1, 2, 3].map((k) => (unorm && upload.ranges[k] ? upload.ranges[k].max - upload.ranges[k].min : 1));
  const offset = [0, 1, 2, 3].map((k) => (unorm && upload.ranges[k] ? upload.ranges[k].min : 0));
  return { tex, scale, offset };
}

function floatTarget() {
  return new WebGLRenderTarget(1, 1, {
    type: FloatType, format: RGBAFormat, minFilter: NearestFilter, magFilter: NearestFilter, depthBuffer: false,
  });
}

export function createNormalMipsScene(canvas, { uniforms: initial, onFrame, onConverged, maxPixels = 120_000 }) {
  const renderer = createRenderer(canvas, { antialias: false });
  const dummy = new DataTexture(new Uint8Array(4), 1, 1);
  dummy.needsUpdate = true;
  const u = {
    uResolution: { value: [1, 1] }, uPass: { value: 0 }, uDebug: { value: 0 },
    uTexA: { value: dummy }, uTexB: { value: dummy },
    uScaleA: { value: [1, 1, 1, 1] }, uOffsetA: { value: [0, 0, 0, 0] },
    uScaleB: { value: [1, 1, 1, 1] }, uOffsetB: { value: [0, 0, 0, 0] },
    uTechnique: { value: 0 }, uChannels: { value: 3 },
    uPrev: { value: dummy }, uSamples: { value: SAMPLES_PER_FRAME }, uFrame: { value: 0 }, uBlend: { value: 1 },
    uTech: { value: dummy }, uTruth: { value: dummy }, uJitter: { value: [0, 0] },
  };
  for (const [k, v] of Object.entries(initial)) u[k] = { value: v };
  const fullscreen = createFullscreenPass(fragment, u);
  const { scene, camera } = fullscreen;
  const rtTech = floatTarget();
  const rtMeasure = floatTarget(); // the error measurement draws here, so the picture's target is left alone
  const rtTruth = [floatTarget(), floatTarget()];
  let textures = {}; // technique → [{ tex, scale, offset }]
  const state = {
    technique: 'naive', channels: 3, samples: 0, cap: 256, truthOn: true, onScreen: false, errors: null, measuring: false, frame: 0, anisotropy: 1,
  };
  let cur = 0;

  function bindTechnique(technique) {
    const [a, b] = textures[technique] ?? [];
    u.uTechnique.value = TECHNIQUES.indexOf(technique);
    u.uTexA.value = a?.tex ?? dummy;
    u.uScaleA.value = a?.scale ?? [1, 1, 1, 1];
    u.uOffsetA.value = a?.offset ?? [0, 0, 0, 0];
    u.uTexB.value = b?.tex ?? dummy;
    u.uScaleB.value = b?.scale ?? [1, 1, 1, 1];
    u.uOffsetB.value = b?.offset ?? [0, 0, 0, 0];
  }

  // Only the display pass reads the targets; the others must not bind the target they draw into.
  function pass(index, target) {
    u.uPass.value = index;
    u.uTech.value = index === 2 ? rtTech.texture : dummy;
    u.uTruth.value = index === 2 ? rtTruth[cur].texture : dummy;
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
  }

  function readTarget(target) {
    const out = new Float32Array(target.width * target.height * 4);
    renderer.readRenderTargetPixels(target, 0, 0, target.width, target.height, out);
    return out;
  }

  // The error of every technique against the converged truth. Each technique is drawn into its own
  // target and read back asynchronously (three.js readRenderTargetPixelsAsync: a pixel-pack buffer
  // and a fence), so the page never waits for the GPU: on a slow GPU six synchronous read-backs
  // would freeze it for seconds. The previous errors stay in state.errors until the new set is
  // complete; a restart or a newer measurement makes a running one stale.
  let measureId = 0;
  let measured = []; // resolvers of whenMeasured()
  let disposed = false;

  const readAsync = (target) => renderer.readRenderTargetPixelsAsync(
    target, 0, 0, target.width, target.height, new Float32Array(target.width * target.height * 4),
  );

  function startMeasure() {
    measureId += 1;
    const id = measureId;
    state.measuring = true;
    runMeasure(id).catch((error) => {
      if (id !== measureId || disposed) return; // a read-back of a context already given up
      stopMeasure();
      throw error;
    });
  }

  async function runMeasure(id) {
    const stale = () => id !== measureId || disposed;
    const truth = await readAsync(rtTruth[cur]);
    if (stale()) return;
    const errors = {};
    for (const technique of TECHNIQUES) {
      bindTechnique(technique);
      pass(0, rtMeasure);
      bindTechnique(state.technique);
      renderer.setRenderTarget(null);
      const image = await readAsync(rtMeasure);
      if (stale()) return;
      errors[technique] = bandedRmse(image, truth, { bands: u.uMaxLevel.value + 1 });
    }
    state.errors = errors;
    stopMeasure();
    onConverged?.(errors);
  }

  function stopMeasure() {
    measureId += 1;
    state.measuring = false;
    const waiting = measured;
    measured = [];
    waiting.forEach((resolve) => resolve());
  }

  function draw() {
    if (!Object.keys(textures).length) return; // nothing to show until the first chains arrive
    u.uDebug.value = 0;
    bindTechnique(state.technique);
    pass(0, rtTech);
    const accumulating = state.truthOn && state.onScreen && state.samples < state.cap;
    if (accumulating) {
      const next = 1 - cur;
      u.uPrev.value = rtTruth[cur].texture;
      u.uFrame.value = state.frame++;
      u.uBlend.value = SAMPLES_PER_FRAME / (state.samples + SAMPLES_PER_FRAME);
      pass(1, rtTruth[next]);
      cur = next;
      state.samples += SAMPLES_PER_FRAME;
      if (state.samples >= state.cap) startMeasure();
    }
    pass(2, null);
    renderer.setRenderTarget(null);
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
    renderer.setPixelRatio(ratio);
    renderer.setSize(width, height, false);
    const buffer = renderer.getDrawingBufferSize(new Vector2());
    u.uResolution.value = [buffer.x, buffer.y];
    for (const rt of [rtTech, rtMeasure, ...rtTruth]) rt.setSize(buffer.x, buffer.y);
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

  function disposeTextures() {
    for (const list of Object.values(textures)) for (const { tex } of list) tex.dispose();
    textures = {};
  }

  return {
    renderer,
    /** 32-bit float textures are filtered only with OES_texture_float_linear (three.js warns without it). */
    floatLinear: renderer.extensions.has('OES_texture_float_linear'),
    /** The largest anisotropic filtering level this GPU offers (1 without the extension). */
    maxAnisotropy: renderer.capabilities.getMaxAnisotropy(),
    uniforms: u,
    state,
    frames,
    /**
     * Uploads every technique's chain (from buildAllChains) and restarts nothing else; uploads,
     * when given, are the chains already packed by uploadLevels (as buildChainsFor returns them).
     */
    setChains(chains, uploads = {}) {
      disposeTextures();
      for (const technique of TECHNIQUES) {
        const packed = uploads[technique] ?? uploadLevels(chains[technique]);
        textures[technique] = packed.map((upload) => makeTexture(upload, state.anisotropy));
      }
      frames.request();
    },
    /** Sets uniforms; truthChanged restarts the ground truth (and the error table). */
    set({ technique, channels, cap, truthOn, anisotropy, ...values }, truthChanged) {
      if (technique !== undefined) state.technique = technique;
      if (anisotropy !== undefined && anisotropy !== state.anisotropy) {
        state.anisotropy = anisotropy;
        u.uAniso.value = anisotropy;
        for (const list of Object.values(textures)) {
          for (const { tex } of list) {
            tex.anisotropy = anisotropy;
            tex.needsUpdate = true; // three.js applies the level when it (re)uploads
          }
        }
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
      const data = readTarget(rtTech);
      u.uDebug.value = 0;
      u.uForcedLevel.value = forced;
      renderer.setRenderTarget(null);
      frames.request();
      return { data, width: rtTech.width, height: rtTech.height };
    },
    /**
     * Shimmer meter: mean |Δ brightness| per pixel of each technique's picture under sub-pixel
     * camera moves. Asynchronous read-backs, as for the errors; resolves null if disposed meanwhile.
     */
    async measureShimmer() {
      const offsets = [[0.5, 0], [0, 0.5], [0.5, 0.5], [0.25, 0.75]];
      const draw = (technique, jitter) => {
        bindTechnique(technique);
        u.uJitter.value = jitter;
        pass(0, rtMeasure);
        u.uJitter.value = [0, 0]; // the picture itself is never jittered
        bindTechnique(state.technique);
        renderer.setRenderTarget(null);
        return readAsync(rtMeasure);
      };
      const result = {};
      try {
        for (const technique of TECHNIQUES) {
          const still = await draw(technique, [0, 0]);
          let sum = 0;
          for (const offset of offsets) {
            const moved = await draw(technique, offset);
            if (disposed) return null;
            sum += meanBrightnessChange(still, moved);
          }
          result[technique] = sum / offsets.length;
        }
      } catch (error) {
        if (disposed) return null; // the context went away under a read-back
        throw error;
      }
      return result;
    },
    /** The current technique's linear picture (RGB, λ in alpha) as drawn now. */
    readTechnique() {
      bindTechnique(state.technique);
      pass(0, rtTech);
      renderer.setRenderTarget(null);
      return readTarget(rtTech);
    },
    toDataURL() {
      draw();
      return canvas.toDataURL('image/png');
    },
    dispose() {
      frames.cancel();
      disposed = true;
      if (state.measuring) stopMeasure();
      resizeObserver.disconnect();
      visibility.disconnect();
      disposeTextures();
      dummy.dispose();
      rtTech.dispose();
      rtMeasure.dispose();
      rtTruth.forEach((rt) => rt.dispose());
      fullscreen.dispose();
      renderer.dispose();
    },
  };
}
