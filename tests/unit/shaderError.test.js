import { describe, expect, it } from 'vitest';
import { explainLog, refusalLine, ShaderError, shaderErrorMessage, sourceLineIndex } from '../../src/gl/shaderError.js';
import { studentFragment, WRAPPER_LINE } from '../../src/panels/shader-lab/studentShader.js';

const SOURCE = ['#version 300 es', 'precision highp float;', 'out vec4 color;', 'void main() {', '  color = vec4(x);', '}'].join('\n');
const LOG = "ERROR: 0:5: 'x' : undeclared identifier\nERROR: 0:5: 'constructor' : not enough data provided for construction\n";

describe('explainLog', () => {
  it('follows each ANGLE "ERROR: 0:LINE:" entry with that line of the source, trimmed', () => {
    expect(explainLog(LOG, SOURCE)).toBe([
      "ERROR: 0:5: 'x' : undeclared identifier",
      '    5: color = vec4(x);',
      "ERROR: 0:5: 'constructor' : not enough data provided for construction",
      '    5: color = vec4(x);',
    ].join('\n'));
  });

  it('leaves entries without a line, or with a line past the source, as the driver wrote them', () => {
    expect(explainLog('WARNING: 0:2: unused\nERROR: 0:99: far away\nsomething else', SOURCE))
      .toBe('WARNING: 0:2: unused\nERROR: 0:99: far away\nsomething else');
    expect(explainLog(null, SOURCE)).toBe('');
    expect(explainLog('  \n', SOURCE)).toBe('');
  });
});

describe('lines after #line directives', () => {
  // The shader lab's wrapper: eight lines of its own, then `#line 1` and the student's code, then
  // `#line 10000` and its main(). The driver counts from each directive (GLSL ES 3.00 §3.4).
  const student = 'float fresnel(float c, float a, float b) {\n  float m = a / b;\n  return m * q;\n}';
  const wrapped = studentFragment(student);

  it('maps a log line through the last #line before it, not the raw line of the source', () => {
    const log = "ERROR: 0:3: 'q' : undeclared identifier";
    expect(explainLog(log, wrapped)).toBe(`${log}\n    3: return m * q;`);
    // Line 3 of the source as written is the wrapper's "precision highp int;": the old mapping.
    expect(wrapped.split('\n')[2]).toBe('precision highp int;');
    expect(explainLog("ERROR: 0:2: 'x' : y", wrapped)).toBe("ERROR: 0:2: 'x' : y\n    2: float m = a / b;");
  });

  it('finds the wrapper\'s own lines after the second directive, and none past the source', () => {
    const at = sourceLineIndex(wrapped, WRAPPER_LINE + 3);
    expect(wrapped.split('\n')[at].trim()).toBe(wrapped.split('\n').find((l) => l.includes('outColor =')).trim());
    expect(sourceLineIndex(wrapped, WRAPPER_LINE + 50)).toBe(-1);
    // Past the student's four lines, line 5 is the wrapper's own, before #line 1.
    expect(sourceLineIndex(wrapped, 5)).toBe(wrapped.split('\n').indexOf('precision highp sampler2D;') + 1);
    expect(explainLog(`ERROR: 0:${WRAPPER_LINE + 60}: far`, wrapped)).toBe(`ERROR: 0:${WRAPPER_LINE + 60}: far`);
  });

  it('keeps the source-string number a directive sets apart', () => {
    const source = ['#version 300 es', 'precision highp float;', '#line 20 3', 'out vec4 color;', 'void main() { color = z; }'].join('\n');
    expect(sourceLineIndex(source, 21, 3)).toBe(4);
    expect(sourceLineIndex(source, 21, 0)).toBe(-1);
    expect(sourceLineIndex(source, 2, 0)).toBe(1);
    expect(explainLog("ERROR: 3:21: 'z' : undeclared identifier", source))
      .toBe("ERROR: 3:21: 'z' : undeclared identifier\n    21: void main() { color = z; }");
  });
});

describe('refusalLine', () => {
  it('is the first line of the log that says error, trimmed, or else its first line', () => {
    expect(refusalLine(new ShaderError({ stage: 'fragment', log: `WARNING: 0:1: unused\n${LOG}`, source: SOURCE })))
      .toBe("ERROR: 0:5: 'x' : undeclared identifier");
    expect(refusalLine({ log: '0(12) : error C1008: undefined variable "q"\u0000' })).toBe('0(12) : error C1008: undefined variable "q"');
    expect(refusalLine({ log: '  Compile failed.\n' })).toBe('Compile failed.');
    expect(refusalLine(new ShaderError({ stage: 'link', log: null }))).toBe('');
  });
});

describe('ShaderError', () => {
  it('carries the stage, the driver\'s log as given, the source and a message with the lines it names', () => {
    const error = new ShaderError({ stage: 'fragment', log: LOG, source: SOURCE });
    expect(error).toBeInstanceOf(Error);
    expect(error.name).toBe('ShaderError');
    expect(error.stage).toBe('fragment');
    expect(error.log).toBe(LOG);
    expect(error.source).toBe(SOURCE);
    expect(error.label).toBe('');
    expect(error.message).toBe(`The fragment shader did not compile:\n${explainLog(LOG, SOURCE)}`);
    expect(error.message.split('\n')[2]).toBe('    5: color = vec4(x);');
  });

  it('says the vertex stage and a failed link as the panels have always shown them', () => {
    expect(new ShaderError({ stage: 'vertex', log: "ERROR: 0:1: 'refused'", source: SOURCE }).message)
      .toBe("The vertex shader did not compile:\nERROR: 0:1: 'refused'\n    1: #version 300 es");
    const link = new ShaderError({ stage: 'link', log: 'Varyings do not match.' });
    expect(link.message).toBe('The shader program did not link:\nVaryings do not match.');
    expect(link.source).toBe('');
  });

  it('names the program when given a label, and reads a missing log as empty', () => {
    const error = new ShaderError({ stage: 'fragment', log: null, source: null, label: 'timing exact-cg, highp' });
    expect(error.log).toBe('');
    expect(error.source).toBe('');
    expect(error.message).toBe('The fragment shader (timing exact-cg, highp) did not compile:\n');
    expect(shaderErrorMessage({ stage: 'link', log: 'no', label: 'x' })).toBe('The shader program (x) did not link:\nno');
  });
});
