// "Error measured by this GPU": every method of a scene's kind evaluated on a WebGL2 context over
// the scene's domain (evaluateMethodsGpu: RGBA32F render, FLOAT read-back, NaN kept bit for bit),
// turned into the advisor's statistics by gpuErrors.errorsFromValues. The panel holds no context
// (its manifest entry says webgl: false): a measurement opens a small one and disposes it when done. Results are kept
// for the page's session, per scene and precision; the benchmark's read-back seeds them too.
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { createContext } from '../../gl/createContext.js';
import { createMethodsGpu, GpuFloatUnavailable, gpuPrecisionInfo } from '../../gl/evaluateMethodsGpu.js';
import { deviceInfo } from '../../gl/timeMethodsGpu.js';
import { domainExtra, domainInputs, errorsFromValues } from '../../methods/gpuErrors.js';
import { methodsOfKind } from '../../methods/methods.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

const yieldToPage = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/**
 * On a context the caller owns, every method of each scene's kind in each GLSL precision.
 * Resolves to { errors: { [sceneId]: { [precision]: { [methodId]: stats } } }, probe
 * (probePrecision: what mediump really is here), claimed (gpuPrecisionInfo: what the driver says),
 * device (deviceInfo) }. Throws GpuFloatUnavailable without float render targets.
 * @param {WebGL2RenderingContext} gl
 * @param {readonly import('../../methods/scenes.js').Scene[]} scenes
 * @param {readonly string[]} precisions
 * @param {{ signal?: AbortSignal, onProgress?: (done: number, total: number, label?: string) => void,
 *   whenVisible?: () => Promise<void> }} [options]
 */
export async function gpuErrorsOn(gl, scenes, precisions, { signal, onProgress, whenVisible } = {}) {
  const gpu = createMethodsGpu(gl);
  try {
    /** @type {Record<string, Record<string, Record<string, import('../../methods/advisor.js').MethodError>>>} */
    const errors = {};
    const total = scenes.reduce((n, s) => n + methodsOfKind(s.kind).length * precisions.length, 0);
    let done = 0;
    for (const scene of scenes) {
      const inputs = domainInputs(scene);
      errors[scene.id] = {};
      for (const precision of precisions) {
        errors[scene.id][precision] = {};
        for (const method of methodsOfKind(scene.kind)) {
          signal?.throwIfAborted();
          const values = gpu.evaluate({ methodId: method.id, precision, inputs, extra: domainExtra(scene, method.id) });
          errors[scene.id][precision][method.id] = errorsFromValues(scene, values);
          done += 1;
          onProgress?.(done, total, t('readingBack', { method: method.label, precision }));
          await yieldToPage(); // one program compile at a time: the page stays responsive
          await whenVisible?.();
        }
      }
    }
    return { errors, probe: gpu.probePrecision(), claimed: gpuPrecisionInfo(gl), device: deviceInfo(gl) };
  } finally {
    gpu.dispose();
  }
}

const session = new Map(); // 'scene|precision' → Promise of { errors: { methodId: stats }, probe, claimed, device }
const settled = new Map(); // the same, once resolved: read synchronously while drawing
let lastProbe = null; // { probe, claimed, device } of the last measurement on this page

/** Problems that will not go away by trying again on this page. */
const permanent = (error) => error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable;

/** The cached measurement of a scene in a precision, or null when there is none (yet). */
export function cachedGpuErrors(scene, precision) {
  return settled.get(`${scene.id}|${precision}`) ?? null;
}

/** What mediump and highp are on this GPU, once anything has been measured here, or null. */
export function gpuPrecisionProbe() {
  return lastProbe;
}

/** Keeps gpuErrorsOn's result (e.g. the benchmark's) for the session. */
export function rememberGpuErrors({ errors, probe, claimed, device }) {
  lastProbe = { probe, claimed, device };
  for (const [sceneId, byPrecision] of Object.entries(errors)) {
    for (const [precision, byMethod] of Object.entries(byPrecision)) {
      const key = `${sceneId}|${precision}`;
      const entry = Object.freeze({ errors: byMethod, ...lastProbe });
      settled.set(key, entry);
      session.set(key, Promise.resolve(entry));
    }
  }
}

/**
 * Measures a scene in one precision ('highp' | 'mediump') on a WebGL2 context opened for it and
 * disposed after; resolves to { errors: { methodId: stats }, probe, claimed, device }. The same
 * promise is returned for the rest of the session. Rejects with WebGL2Unavailable or
 * GpuFloatUnavailable where the GPU cannot do it (kept: asking again gives the same answer).
 */
export function measureGpuErrors(scene, precision) {
  const key = `${scene.id}|${precision}`;
  if (!session.has(key)) {
    const job = (async () => {
      await yieldToPage(); // let the panel say "measuring" before the first compile
      const canvas = document.createElement('canvas');
      canvas.width = 1;
      canvas.height = 1;
      const context = createContext(canvas);
      try {
        const result = await gpuErrorsOn(context.gl, [scene], [precision]);
        rememberGpuErrors(result);
        return settled.get(key);
      } finally {
        context.dispose(); // releases the context and its place in the page's budget
      }
    })();
    job.catch((error) => { if (!permanent(error)) session.delete(key); });
    session.set(key, job);
  }
  return session.get(key);
}
