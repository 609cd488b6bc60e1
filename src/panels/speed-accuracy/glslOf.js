// @ts-check
// Which error source reads values back from this GPU, and in which GLSL precision: the runs
// choose what to measure by it, the words say it. No words here, so the runs may import it.

/** @type {Readonly<Record<string, 'highp' | 'mediump'>>} */
const GLSL = Object.freeze({ 'gpu-highp': 'highp', 'gpu-mediump': 'mediump' });

/**
 * The GLSL precision an error source reads back in ('gpu-highp' → highp), or null for the JS emulation.
 * @param {string} source
 * @returns {'highp' | 'mediump' | null}
 */
export function glslOf(source) {
  return Object.hasOwn(GLSL, source) ? GLSL[source] : null;
}
