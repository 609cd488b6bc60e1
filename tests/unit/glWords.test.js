// The words of src/gl that reach a page come from the catalogue ("gl"); the driver's log is kept
// as the driver wrote it.
import { describe, expect, it } from 'vitest';
import { ShaderError } from '../../src/gl/shaderError.js';
import { createContext } from '../../src/gl/createContext.js';
import { timerName, TIMER_QUERY, WALL_TIMER } from '../../src/gl/timeMethodsGpu.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

const LOG = "ERROR: 0:2: 'q' : undeclared identifier";
const SOURCE = '#version 300 es\nvoid main() { q; }';

describe('the words of src/gl in another language', () => {
  usePseudoLocale();

  it('a refused shader: the lab\'s sentence translated, the driver\'s log and its source line as they were', () => {
    for (const details of [
      { stage: 'fragment', log: LOG, source: SOURCE }, { stage: 'vertex', log: LOG, source: SOURCE, label: 'x' },
      { stage: 'link', log: 'Varyings do not match.' }, { stage: 'link', log: 'no', label: 'x' },
    ]) {
      const { message } = new ShaderError(details);
      expect(message.startsWith('⟦')).toBe(true);
      expect(message).toContain(details.log);
      expect(wordsOutside(message)).toBe('');
    }
    expect(new ShaderError({ stage: 'fragment', log: LOG, source: SOURCE }).message).toContain('\n    2: void main() { q; }');
  });

  it('no WebGL2, and the wall-clock timer, in words; an extension keeps its name', () => {
    expect(() => createContext({})).toThrow(/^⟦/); // Node has no WebGL2RenderingContext
    expect(wordsOutside(timerName(WALL_TIMER))).toBe('');
    expect(timerName(WALL_TIMER)).not.toBe(WALL_TIMER);
    expect(timerName(TIMER_QUERY)).toBe(TIMER_QUERY);
  });
});
