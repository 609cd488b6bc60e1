// @ts-check
// Why reading the errors back from this GPU failed, in words for the panel's notice, from the
// error itself: a refused shader is not a missing float render target, and a lost context is
// neither. Pure (the error classes carry no WebGL), so each wording is tested in Node.
import { WebGL2Unavailable } from '../../gl/contextBudget.js';
import { GpuFloatUnavailable } from '../../gl/evaluateMethodsGpu.js';
import { refusalLine, ShaderError } from '../../gl/shaderError.js';

const FALLBACK = 'so the errors shown are the JavaScript emulation.';

/** The notice's sentence for an error of the GPU read-back (measureGpuErrors). */
export function readBackProblem(/** @type {unknown} */ error) {
  if (error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable) {
    return `${error.message} Reading errors back needs WebGL2 with float render targets, ${FALLBACK}`;
  }
  if (error instanceof ShaderError) {
    // The driver's first error line (the model logs the whole log with the source lines it names).
    const first = refusalLine(error);
    const what = error.stage === 'link' ? 'link' : 'compile';
    return `This GPU could not ${what} the shader that evaluates a method${error.label ? ` (${error.label})` : ''}, ${FALLBACK}`
      + (first ? ` The driver said: ${first}` : '');
  }
  const message = error instanceof Error ? error.message : String(error);
  return `Reading the errors back from this GPU failed (${message}), ${FALLBACK}`;
}
