// @ts-check
// Why reading the errors back from this GPU failed, in words for the panel's notice, from the
// error itself: a refused shader is not a missing float render target, and a lost context is
// neither. Pure (the error classes carry no WebGL), so each wording is tested in Node.
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { GpuFloatUnavailable } from '../../gl/evaluateMethodsGpu.js';
import { refusalLine, ShaderError } from '../../gl/shaderError.js';

const t = messages('speed-accuracy', english);

/** The notice's sentence for an error of the GPU read-back (measureGpuErrors). */
export function readBackProblem(/** @type {unknown} */ error) {
  if (error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable) {
    return t('needsFloatTargets', { problem: error.message });
  }
  if (error instanceof ShaderError) {
    // The driver's first error line (the runs log the whole log with the source lines it names).
    const first = refusalLine(error);
    const stage = error.stage === 'link' ? 'link' : 'compile';
    const refused = error.label ? t('shaderRefusedNamed', { stage, label: error.label }) : t('shaderRefused', { stage });
    return first ? `${refused} ${t('driverSaid', { line: first })}` : refused;
  }
  const message = error instanceof Error ? error.message : String(error);
  return t('readBackFailed', { problem: message });
}
