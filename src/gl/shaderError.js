// The one error a shader the driver refuses throws (compileProgram.js), whoever compiled it: a
// panel's picture, the method evaluator, the timing passes or a student's code. Pure (no WebGL),
// so the wording and the line mapping are tested in Node. The lab's words around the driver's log
// are the catalogue's ("gl"); the log stays as the driver wrote it.
import english from 'virtual:messages/en/gl';
import { messages } from '../i18n/messages.js';

const t = messages('gl', english);

// A #line directive: "#line line" or "#line line source-string-number" (GLSL ES 3.00 §3.4).
const LINE_DIRECTIVE = /^\s*#\s*line\s+(\d+)(?:\s+(\d+))?\s*(?:\/\/.*)?$/;

/**
 * The index (0-based) in `source` of the line the driver calls line `line` of source string
 * `string`, or -1. After "#line L" the next line is line L (GLSL ES 3.00 §3.4), so a source that
 * restarts its count (the shader lab's `#line 1` before the student's code) can hold a line number
 * twice: the last #line whose stretch reaches it wins, as the code after a directive is the code
 * the directive was written for.
 */
export function sourceLineIndex(source, line, string = 0) {
  const lines = String(source ?? '').split('\n');
  const stretches = [{ start: 0, first: 1, string: 0 }];
  lines.forEach((text, i) => {
    const m = LINE_DIRECTIVE.exec(text);
    if (m) stretches.push({ start: i + 1, first: Number(m[1]), string: m[2] === undefined ? stretches.at(-1).string : Number(m[2]) });
  });
  for (let k = stretches.length - 1; k >= 0; k -= 1) {
    const { start, first, string: s } = stretches[k];
    const end = k + 1 < stretches.length ? stretches[k + 1].start - 1 : lines.length; // the next directive's own line ends it
    const index = start + line - first;
    if (s === string && line >= first && index < end) return index;
  }
  return -1;
}

/** The driver's log, each "ERROR: S:LINE:" (ANGLE's form) followed by that line of the source. */
export function explainLog(log, source) {
  const lines = String(source ?? '').split('\n');
  return String(log ?? '').trim().split('\n').map((entry) => {
    const m = /^\s*ERROR:\s*(\d+):(\d+):/.exec(entry);
    if (!m) return entry;
    const index = sourceLineIndex(source, Number(m[2]), Number(m[1]));
    return index >= 0 ? `${entry}\n    ${m[2]}: ${lines[index].trim()}` : entry;
  }).join('\n');
}

/**
 * The driver's words on a refused shader in one line, for a sentence on the page: the first line
 * of its log that says error, else its first line; '' when the driver gave no log.
 */
export function refusalLine(error) {
  // eslint-disable-next-line no-control-regex
  const lines = String(error?.log ?? '').split('\n').map((l) => l.replace(/[\u0000-\u001f\u007f]/g, '').trim()).filter(Boolean);
  return lines.find((l) => /\berror\b/i.test(l)) ?? lines[0] ?? '';
}

/**
 * The message of a refused shader: which stage, then the driver's log (for a compile, with the
 * source lines it names). label, if any, names the program (the timing pass of a method, say).
 */
export function shaderErrorMessage({ stage, log = '', source = '', label = '' }) {
  if (stage === 'link') return label ? t('programNotLinkedNamed', { label, log }) : t('programNotLinked', { log });
  // A message per stage, without a select: these words come with the first picture, and a select
  // would bring the message runtime with them.
  const args = { label, log: explainLog(log, source) };
  const which = stage === 'vertex' ? 'vertex' : 'fragment';
  return t(label ? `${which}NotCompiledNamed` : `${which}NotCompiled`, args);
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
