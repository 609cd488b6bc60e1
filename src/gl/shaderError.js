// The one error a shader the driver refuses throws (compileProgram.js), whoever compiled it: a
// panel's picture, the method evaluator, the timing passes or a student's code. Pure (no WebGL),
// so the wording and the line mapping are tested in Node.

/** The driver's log, each "ERROR: 0:LINE:" (ANGLE's form) followed by that line of the source. */
export function explainLog(log, source) {
  const lines = String(source ?? '').split('\n');
  return String(log ?? '').trim().split('\n').map((entry) => {
    const line = /^\s*ERROR:\s*\d+:(\d+):/.exec(entry)?.[1];
    return line && lines[line - 1] !== undefined ? `${entry}\n    ${line}: ${lines[line - 1].trim()}` : entry;
  }).join('\n');
}

/**
 * The message of a refused shader: which stage, then the driver's log (for a compile, with the
 * source lines it names). label, if any, names the program (the timing pass of a method, say).
 */
export function shaderErrorMessage({ stage, log = '', source = '', label = '' }) {
  const which = label ? ` (${label})` : '';
  return stage === 'link'
    ? `The shader program${which} did not link:\n${log}`
    : `The ${stage} shader${which} did not compile:\n${explainLog(log, source)}`;
}

/**
 * A shader did not compile, or the program did not link. stage: 'vertex' | 'fragment' | 'link';
 * log: the driver's info log as it gave it ('' when it gave none); source: the refused stage's
 * source ('' for a link); label: what the program was for, or ''. The message holds the log with
 * the source lines it names (shaderErrorMessage).
 */
export class ShaderError extends Error {
  /** @param {{ stage: 'vertex' | 'fragment' | 'link', log?: string | null, source?: string | null, label?: string }} details */
  constructor({ stage, log = '', source = '', label = '' }) {
    const details = { stage, log: log ?? '', source: source ?? '', label };
    super(shaderErrorMessage(details));
    this.name = 'ShaderError';
    this.stage = details.stage;
    this.log = details.log;
    this.source = details.source;
    this.label = details.label;
  }
}
