import { describe, expect, it } from 'vitest';
import { explainLog, ShaderError, shaderErrorMessage } from '../../src/gl/shaderError.js';

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
