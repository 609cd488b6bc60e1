// Properties of the shader lab's doors: the code link (codeCodec.js), the check before the GPU
// (studentShader.js), and code kept in this browser (storedCode.js). Loops, preprocessor lines
// (token pasting lives only there) and precision statements must be refused however they are
// spelled across comments, continuations and line ends.
import { afterEach, describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { deflateSync } from 'fflate';
import { decodeCode, encodeCode, useDeflate } from '../../src/panels/shader-lab/codeCodec.js';
import { WRAPPER_LINE, checkStudentCode, studentFragment } from '../../src/panels/shader-lab/studentShader.js';
import { readStored, writeStored } from '../../src/panels/shader-lab/storedCode.js';
import { problemText } from '../../src/panels/shader-lab/words.js';
import { exerciseById } from '../../src/panels/shader-lab/exercises.js';
import { schema } from '../../src/panels/shader-lab/schema.js';
import { parseValue } from '../../src/host/params.js';
import { anyText, anyValue } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

/**
 * What the compiler reads, modelled apart from the check: continuations join lines first, then
 * comments go from left to right (GLSL ES 3.00 §3.2–3.4). Lines that were joined stay joined.
 */
function compilerView(code) {
  const joined = code.replace(/\\(\r\n|\r|\n)/g, '').replace(/\r\n?/g, '\n');
  return joined.replace(/\/\/[^\n]*|\/\*[\s\S]*?\*\//g, (c) => c.replace(/[^\n]/g, ' '));
}
const forbidden = (view) => /\b(for|while|do)\b/.test(view) || /(^|\n)[ \t\v\f]*#/.test(view) || /\bprecision\b/.test(view);

/** Code assembled from the pieces a loop or a directive could hide behind. */
const PIECES = ['for (;;) {}', 'while (true) {}', 'do {} while (true);', 'fo', 'r', 'whi', 'le', '#define F(a, b) a##b', '#', '##', 'F(fo, r)',
  '#if 1', '#line 1', '#version 300 es', 'precision highp float;', '//', '/*', '*/', '\\', '\\\n', '\\\r\n', '\n', '\r', '\r\n', ' ', '\t',
  '\u000b', '\u000c', '\u2028', 'float fresnel(float c, float a, float b) {', 'return c;', '}', 'x', ';', '\u0000', 'é', '𝟙'];
const assembled = fc.array(fc.constantFrom(...PIECES), { maxLength: 14 }).map((parts) => parts.join(''));

describe('the check before the GPU', () => {
  it('refuses every code in which the compiler would find a loop, a preprocessor line or a precision statement', () => {
    check(fc.property(assembled, (code) => {
      if (forbidden(compilerView(code))) expect(checkStudentCode(code).length, JSON.stringify(code)).toBeGreaterThan(0);
    }), 400);
  });

  it('never throws, and each problem has a code, words for it and a line of the code or none', () => {
    const exercise = exerciseById('exact');
    check(fc.property(fc.oneof(assembled, anyText, anyValue), (code) => {
      const problems = checkStudentCode(code);
      const lines = typeof code === 'string' ? code.split(/\r\n?|\n/).length : 0;
      for (const problem of problems) {
        const { line } = problem;
        expect(['noCode', 'tooLong', 'loop', 'continuation', 'directive', 'precision']).toContain(problem.code);
        expect(problemText(problem, exercise)).toMatch(/^\p{Lu}.*\.$/u);
        expect(line === null || (Number.isInteger(line) && line >= 1 && line <= lines)).toBe(true);
      }
    }), 200);
  });

  it('code it takes leaves the wrapper\'s own directives the only ones in the shader', () => {
    check(fc.property(assembled, (code) => {
      if (checkStudentCode(code).length) return;
      const directives = compilerView(studentFragment(code)).split('\n').filter((l) => /^\s*#/.test(l)).map((l) => l.trim());
      expect(directives).toEqual(['#version 300 es', '#line 1', `#line ${WRAPPER_LINE}`]);
    }), 300);
  });
});

describe('the code link', () => {
  afterEach(() => useDeflate(null));

  it('reads any text without throwing: the code, or null', () => {
    const compactish = fc.tuple(fc.stringMatching(/^[0-9a-z]{1,7}$/), fc.stringMatching(/^[A-Za-z0-9_-]{0,40}$/)).map(([n, b]) => `*${n}.${b}`);
    check(fc.property(fc.oneof(anyText, compactish), (raw) => {
      const text = decodeCode(raw);
      expect(text === null || typeof text === 'string').toBe(true);
    }), 300);
  });

  it('a made-up compact code that once looped the inflater for ever is refused at once', () => {
    expect(decodeCode('*jc0.3B-1-a-')).toBe(null);
    expect(decodeCode('*d8.t_-_O')).toBe(null);
  });

  it('code → link → code is the same code, with the panel\'s deflate and before it arrives', () => {
    const code = fc.oneof(fc.string({ unit: 'grapheme', maxLength: 300 }), fc.string({ unit: 'grapheme', maxLength: 30 }).map((t) => `*${t}`), anyText)
      .filter((t) => t.length <= schema.code.maxLength);
    for (const deflate of [null, deflateSync]) {
      useDeflate(deflate);
      check(fc.property(code, (text) => {
        // A link holds Unicode text: a lone surrogate half (no character) comes back as U+FFFD.
        const well = text.toWellFormed();
        expect(decodeCode(encodeCode(text))).toBe(deflate || text.startsWith('*') ? well : text);
        // Through the link as the host writes and reads it.
        const link = new URLSearchParams({ code: encodeCode(text) }).toString();
        expect(parseValue(schema.code, new URLSearchParams(link).get('code'))).toEqual({ ok: true, value: well });
      }), 150);
    }
  });
});

describe('code kept in this browser', () => {
  const original = globalThis.window;
  afterEach(() => { globalThis.window = original; });

  it('whatever storage holds or throws, reading it gives a text or null, and the panel takes it or says why', () => {
    check(fc.property(fc.oneof(anyText, fc.constant(null)), fc.boolean(), (held, refuses) => {
      globalThis.window = /** @type {any} */ ({
        localStorage: {
          getItem: () => { if (refuses) throw new Error('SecurityError'); return held; },
          setItem: () => { throw new Error('QuotaExceededError'); },
          removeItem: () => {},
        },
      });
      const stored = readStored('schlick');
      expect(stored === null || typeof stored === 'string').toBe(true);
      expect(() => writeStored('schlick', 'float x;')).not.toThrow();
      if (stored === null) return;
      const read = parseValue(schema.code, stored);
      if (read.ok) expect(read.value.length).toBeLessThanOrEqual(schema.code.maxLength);
      else expect(read.reason).toMatch(/\S/);
    }), 150);
  });
});
