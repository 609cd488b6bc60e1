// Where the speed-accuracy panel's errors come from: the JS emulation at the scene's precision
// (rounding.js contexts, advisor.methodError), or values read back from this GPU in highp or
// mediump (measureGpuErrors.js). The options of the "Error measured by" control, and the words
// the chart, the recommendation, describe() and the CSV use to say which one was used.

// Short labels: lil-gui's select is narrow. The chart title and the reason give the details.
export const ERROR_SOURCES = Object.freeze({
  js: 'JS emulation',
  'gpu-highp': 'This GPU, highp',
  'gpu-mediump': 'This GPU, mediump',
});

const GLSL = Object.freeze({ 'gpu-highp': 'highp', 'gpu-mediump': 'mediump' });

/** The GLSL precision a source reads back in, or null for the JS emulation. */
export function glslOf(source) {
  return GLSL[source] ?? null;
}

export const PRECISION_WORDS = Object.freeze({ fp32: 'float32 (highp)', fp16: 'float16 (mediump)' });

/**
 * Words for an error source. source: 'js' | 'gpu-highp' | 'gpu-mediump'; scene: for its
 * precision; renderer: this GPU's renderer string (for the sentence). Returns { short (chart
 * title and pick), phrase (describe(): "in …" / "measured …"), sentence (after the reason) }.
 */
export function sourceWords(source, scene, renderer = '') {
  const glsl = glslOf(source);
  if (!glsl) {
    const words = PRECISION_WORDS[scene.precision] ?? scene.precision;
    return {
      short: `${words}, JS emulation`,
      phrase: `in ${words} (JS emulation)`,
      sentence: `Errors: JavaScript emulation of ${words}, every operation rounded to that format.`,
    };
  }
  return {
    short: `this GPU's ${glsl}`,
    phrase: `with errors measured on this GPU in ${glsl}`,
    sentence: `Errors: measured on this GPU${renderer ? ` (${renderer})` : ''} in ${glsl}: every sample rendered to an `
      + 'RGBA32F target and read back, against the float64 reference.',
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
  const claim = claimed?.mediump ? ` (the driver claims ${claimed.mediump.precision + 1})` : '';
  if (probe.mediumpIsFullPrecision) {
    return `mediump runs at full precision on this GPU: ${probe.mediumpBits} significand bits measured${claim}, `
      + 'so its errors equal highp\'s. The phone scene\'s JS float16 shows true half precision.';
  }
  return `mediump runs at reduced precision on this GPU: ${probe.mediumpBits} significand bits measured${claim}; float16 has 11.`;
}
