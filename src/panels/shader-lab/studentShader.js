// @ts-check
// The student's GLSL in a shader the page builds: never evaluated as JavaScript, only compiled by
// the GPU driver into a read-back program. Before that, code that could hang or break the page is
// refused: loops (a loop that never ends stalls the GPU until the browser resets it, and a
// Fresnel function needs none), every preprocessor line (#define could hide a loop or reach into
// the page's code; #version, #line, #extension would change the wrapper), line continuations (a
// backslash at a line's end joins it to the next, which could spell a loop in two pieces),
// precision statements (the mediump exercise is about the precision the page sets), and sizes far
// past any Fresnel function. `#line 1` before the
// student's code makes the driver's error lines the student's own (GLSL ES 3.00 §3.4); the wrapper
// after it starts at line WRAPPER_LINE, so its errors are told apart.
// What stopped the code is kept as a code with its line (and the driver's words as it wrote them):
// words.js says it in the page's language.
import { MAX_CODE } from './exerciseIds.js';

export { MAX_CODE };
export const WRAPPER_LINE = 10000;

/**
 * Why code is not graded, at the student's line (null: no line of theirs). The page's check:
 * 'noCode', 'tooLong' (its length and the most allowed), 'loop', 'continuation', 'directive',
 * 'precision'. The driver's refusal, its words kept as it wrote them (text): 'driver' at a line of
 * the student's, 'afterLastLine' (a syntax error in the page's wrapper: an unclosed brace or a
 * missing ;) or 'missingFunction' (any other error there: the function the page calls is not
 * defined). 'refused': the driver refused the shader and named no line (the error it threw).
 * @typedef {{ line: number | null, code: 'noCode' | 'loop' | 'continuation' | 'directive' | 'precision' }
 *   | { line: null, code: 'tooLong', length: number, max: number }
 *   | { line: number | null, code: 'driver' | 'afterLastLine' | 'missingFunction', text: string }
 *   | { line: null, code: 'refused', error: import('../../gl/shaderError.js').ShaderError }} CodeProblem
 */

/**
 * Problems that refuse the code before it reaches the GPU (empty: fine).
 * @param {unknown} code
 * @returns {CodeProblem[]}
 */
export function checkStudentCode(code) {
  /** @type {CodeProblem[]} */
  const problems = [];
  if (typeof code !== 'string' || !code.trim()) return [{ line: null, code: 'noCode' }];
  if (code.length > MAX_CODE) problems.push({ line: null, code: 'tooLong', length: code.length, max: MAX_CODE });
  // Lines as the compiler counts them (\r\n, \r and \n all end one). Comments go in one pass from
  // left to right, as the compiler reads them (a word in a comment is no loop); their newlines
  // stay, so lines still count.
  const lines = code.replace(/\r\n?/g, '\n');
  const bare = lines.replace(/\/\/[^\n]*|\/\*[\s\S]*?\*\//g, (c) => c.replace(/[^\n]/g, ' '));
  // Continuations are looked for before comments go, as the compiler joins lines before it reads
  // comments: a "// …\" comment runs on through the next line, so a "/*" there opens none, and
  // what that seemed to hide (a loop) is code (GLSL ES 3.00 §3.2).
  const raw = lines.split('\n');
  bare.split('\n').forEach((text, i) => {
    const line = i + 1;
    const refuse = (/** @type {'loop' | 'continuation' | 'directive' | 'precision'} */ why) => problems.push({ line, code: why });
    if (/\b(for|while|do)\b/.test(text)) refuse('loop');
    if (/\\\s*$/.test(raw[i])) refuse('continuation');
    if (/^\s*#/.test(text)) refuse('directive');
    if (/\bprecision\b/.test(text)) refuse('precision');
  });
  return problems;
}

/**
 * The read-back fragment shader around the student's code: precision as asked (the student's
 * function inherits it), inputs read from float textures at full float32, the result written to
 * an RGBA32F target. kind: 'dielectric' calls fresnel(cos, nI, nT); 'conductor' calls
 * fresnelConductor(cos, n, k) with n from the inputs' yzw and k from the extra texture.
 * @param {string} code
 * @param {{ kind?: string, precision?: string }} [options]
 */
export function studentFragment(code, { kind = 'dielectric', precision = 'highp' } = {}) {
  const call = kind === 'conductor'
    ? 'vec4(fresnelConductor(a.x, a.yzw, texelFetch(uExtra, p, 0).xyz), 1.0)'
    : 'vec4(fresnel(a.x, a.y, a.z), 0.0, 0.0, 1.0)';
  return `#version 300 es
precision ${precision === 'mediump' ? 'mediump' : 'highp'} float;
precision highp int;
precision highp sampler2D;
uniform sampler2D uInputs;
uniform sampler2D uExtra;
out highp vec4 outColor;
#line 1
${code}
#line ${WRAPPER_LINE}
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  highp vec4 a = texelFetch(uInputs, p, 0);
  outColor = ${call};
}
`;
}

/**
 * The driver's log as problems at the student's lines (null for the wrapper's, or none).
 * Drivers write "ERROR: 0:12: 'x' : undeclared identifier" (ANGLE) or "0(12) : error …"
 * (some others); an error past the student's code is a missing function, or an unclosed brace.
 * @param {unknown} log
 * @returns {CodeProblem[]}
 */
export function readCompileLog(log) {
  /** @type {CodeProblem[]} */
  const entries = [];
  for (const raw of String(log ?? '').split('\n')) {
    // eslint-disable-next-line no-control-regex
    const text = raw.replace(/[\u0000-\u001f\u007f]/g, '').trim(); // drivers end the log with a NUL
    if (!text || /^(WARNING|INFO)/i.test(text)) continue;
    const m = /^(?:ERROR:\s*)?\d+[:(](\d+)\)?\s*:\s*(?:error\s*[^:]*:\s*)?(.*)$/i.exec(text);
    if (!m) {
      if (!/compilation errors?/i.test(text)) entries.push({ line: null, code: 'driver', text: text.replace(/^ERROR:\s*/i, '') });
      continue;
    }
    const line = Number(m[1]);
    const said = m[2].trim();
    if (line < WRAPPER_LINE) entries.push({ line, code: 'driver', text: said });
    // Past the student's last line: an unclosed brace or a missing ; shows up in the page's code.
    else if (/syntax error|unexpected|end of/i.test(said)) entries.push({ line: null, code: 'afterLastLine', text: said });
    else entries.push({ line: null, code: 'missingFunction', text: said });
  }
  return entries;
}
