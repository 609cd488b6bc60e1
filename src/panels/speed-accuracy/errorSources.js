// Where the speed-accuracy panel's errors come from: the JS emulation at the scene's precision
// (rounding.js contexts, advisor.methodError), or values read back from this GPU in highp or
// mediump (measureGpuErrors.js). The words the chart, the recommendation, describe() and the CSV
// use to say which one was used (the control's options are the catalogue's "controls").
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';
import { contextFor } from '../../methods/rounding.js';
import { emulationGapWords } from '../shared/emulationGapWords.js';
import { glslOf } from './glslOf.js';

const t = messages('speed-accuracy', english);

/** A scene precision in words ('fp32' → float32 (highp)); anything else as it is. */
export const precisionWords = (precision) => (precision === 'fp32' || precision === 'fp16' ? contextFor(precision).label : precision);

/**
 * Words for an error source. source: 'js' | 'gpu-highp' | 'gpu-mediump'; scene: for its
 * precision; renderer: this GPU's renderer string (for the sentence). Returns { short (chart
 * title and pick), phrase (describe(): "in …" / "measured …"), sentence (after the reason) }.
 */
export function sourceWords(source, scene, renderer = '') {
  const glsl = glslOf(source);
  if (!glsl) {
    const precision = precisionWords(scene.precision);
    // The emulation rounds exactly; a GPU does not (emulationGap.js): said wherever emulated
    // float32 or float16 errors are shown.
    const gap = scene.precision === 'fp32' || scene.precision === 'fp16' ? ` ${t('emulationGap', emulationGapWords())}` : '';
    const sentence = `${t('jsSentence', { precision })}${gap}`;
    return { short: t('jsShort', { precision }), phrase: t('jsPhrase', { precision }), sentence };
  }
  return {
    short: t('gpuShort', { precision: glsl }),
    phrase: t('gpuPhrase', { precision: glsl }),
    sentence: renderer ? t('gpuSentenceNamed', { renderer, precision: glsl }) : t('gpuSentence', { precision: glsl }),
  };
}

/**
 * What mediump is here, for the note beside the control: probe (evaluateMethodsGpu
 * probePrecision, measured by rendering 1 + 2^-f) and claimed (gpuPrecisionInfo, the driver's
 * word, which Safari/iOS has got wrong: webglfundamentals "WebGL Precision Issues"). '' before
 * anything was measured.
 */
export function mediumpNote(known) {
  if (!known?.probe) return '';
  const { probe, claimed } = known;
  const args = {
    bits: String(probe.mediumpBits), claimed: claimed?.mediump ? String(claimed.mediump.precision + 1) : '', ...emulationGapWords(),
  };
  if (probe.mediumpIsFullPrecision) return t(args.claimed ? 'mediumpFullClaimed' : 'mediumpFull', args);
  return t(args.claimed ? 'mediumpReducedClaimed' : 'mediumpReduced', args);
}
