import { describe, expect, it } from 'vitest';
import {
  applyParams, defaults, describeProblem, formatValue, parseValue, readParams, stepDecimals, writeParams,
} from '../../src/host/params.js';
import { schema } from '../../src/panels/spheres/schema.js';

const q = (s) => new URLSearchParams(s);

describe('URL schema parsing', () => {
  it('reads good values of every type', () => {
    const { values, problems } = readParams(schema, q('nI=1.333&nT=1&kd=00ff80&errScale=0.1'));
    expect(problems).toEqual([]);
    expect(values).toMatchObject({ nI: 1.333, nT: 1, kd: '#00ff80', errScale: '0.1', lightAz: 35 });
  });
  it('absent keys take their defaults silently', () => {
    expect(readParams(schema, q(''))).toEqual({ values: defaults(schema), problems: [] });
  });
  it('bad values fall back to the default and are reported by name', () => {
    const { values, problems } = readParams(schema, q('nI=abc&nT=9&kd=red&errScale=huge&viewEl=&lightAz=1e999'));
    expect(values).toEqual(defaults(schema));
    expect(problems.map((p) => p.key)).toEqual(['nI', 'nT', 'kd', 'lightAz', 'errScale', 'viewEl']);
    expect(describeProblem(problems[0])).toBe('nI=abc is not a number; using 1.');
    expect(describeProblem(problems[1])).toBe('nT=9 is outside 1 to 3; using 1.5.');
    expect(describeProblem(problems[2])).toMatch(/kd=red is not a colour/);
    expect(problems[5].reason).toBe('is not a number');
  });
  it('parses booleans and rejects nonsense', () => {
    const spec = { type: 'boolean', default: false };
    expect(parseValue(spec, 'true')).toEqual({ ok: true, value: true });
    expect(parseValue(spec, '0')).toEqual({ ok: true, value: false });
    expect(parseValue(spec, 'maybe').ok).toBe(false);
  });
  it('writes short values that read back to the same state', () => {
    const values = { ...defaults(schema), nI: 1.3333, nT: 2.4166, kd: '#123abc' };
    const search = writeParams(schema, values, new URLSearchParams());
    expect(search.get('nI')).toBe('1.3333');
    expect(search.get('nT')).toBe('2.4166');
    expect(search.get('kd')).toBe('123abc');
    expect(search.has('viewDist')).toBe(false); // defaults stay out of the link
    expect(readParams(schema, search)).toEqual({ values, problems: [] });
  });
  it('prefixes keys for panels that share a page', () => {
    const search = writeParams(schema, { ...defaults(schema), nT: 2 }, q('spheres.nI=1.2&other=1'), 'spheres.');
    expect(search.toString()).toBe('other=1&spheres.nT=2'); // back to its default, nI leaves the link
    expect(readParams(schema, q('spheres.nT=2'), 'spheres.').values.nT).toBe(2);
  });
  it('step decimals and number formatting', () => {
    expect(stepDecimals(0.0001)).toBe(4);
    expect(stepDecimals(0.01)).toBe(2);
    expect(stepDecimals(1)).toBe(0);
    expect(formatValue({ type: 'number', step: 0.01 }, 1.5)).toBe('1.5');
    expect(formatValue({ type: 'number', step: 1 }, -35)).toBe('-35');
  });
  it('applies partial updates, rejecting unknown keys and bad values', () => {
    const values = defaults(schema);
    const { applied, rejected } = applyParams(schema, values, { nT: 2, nI: -1, bogus: 3 });
    expect(applied).toEqual({ nT: 2 });
    expect(values.nT).toBe(2);
    expect(values.nI).toBe(1);
    expect(rejected.map((r) => r.key)).toEqual(['nI', 'bogus']);
  });
});

describe('values from outside that name inherited things or run code when turned to text', async () => {
  const { applyParams, describeProblem, parseValue, rawText } = await import('../../src/host/params.js');
  const schema = {
    nT: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.01, label: 'n_t', aliases: ['n'] },
    mode: { type: 'enum', default: 'a', options: { a: 'A', b: 'B' }, label: 'Mode' },
  };
  const hostile = { toString: 'x', valueOf: 1 }; // String(hostile) throws
  it('an inherited name is not a parameter, and says so', () => {
    for (const name of ['constructor', 'toString', 'valueOf', 'hasOwnProperty', '__proto__']) {
      const update = JSON.parse(`{${JSON.stringify(name)}: 1}`);
      const values = { nT: 1.5, mode: 'a' };
      const { rejected, changed } = applyParams(schema, values, update);
      expect(rejected.map((r) => [r.key, r.reason]), name).toEqual([[name, 'is not a parameter of this panel']]);
      expect(changed).toEqual([]);
      expect(Object.keys(values)).toEqual(['nT', 'mode']);
    }
  });
  it('an object whose toString is not a function is refused and named without calling it', () => {
    expect(() => parseValue(schema.mode, hostile)).not.toThrow();
    expect(parseValue(schema.mode, hostile).ok).toBe(false);
    expect(parseValue(schema.mode, ['a']).ok).toBe(false);
    const { rejected } = applyParams(schema, { nT: 1.5, mode: 'a' }, { mode: hostile, nT: hostile });
    expect(rejected).toHaveLength(2);
    expect(rejected.map(describeProblem)).toEqual([
      'mode=(an object) is not one of a, b; ignored.', 'nT=(an object) is not a number; ignored.',
    ]);
    expect(rawText('x'.repeat(100))).toBe(`${'x'.repeat(40)}…`);
    expect(rawText(null)).toBe('null');
  });
});

describe('whole-number parameters', async () => {
  const { parseValue } = await import('../../src/host/params.js');
  const { schema: mips } = await import('../../src/panels/normal-mips/schema.js');
  it('an index takes whole numbers only (a texel 0.75 read NaN normals)', () => {
    for (const key of ['level', 'texelLevel', 'texelX', 'texelY']) {
      expect(mips[key].integer, key).toBe(true);
      expect(parseValue(mips[key], '0.7501')).toEqual({ ok: false, reason: 'is not a whole number' });
      expect(parseValue(mips[key], 3)).toEqual({ ok: true, value: 3 });
    }
  });
});

describe('minus zero', async () => {
  const { formatValue, parseValue } = await import('../../src/host/params.js');
  const spec = { type: 'number', default: 0, min: -10, max: 10, step: 0.1, label: 'x' };
  it('is read as 0, and a tiny negative value is written as 0 (the link wrote -0, which read back as another link)', () => {
    for (const raw of ['-0', -0, '-0.0']) expect(Object.is(parseValue(spec, raw).value, 0), String(raw)).toBe(true);
    expect(formatValue(spec, -5e-324)).toBe('0');
    expect(formatValue(spec, -0.04)).toBe('0');
    expect(formatValue(spec, -0.06)).toBe('-0.1');
  });
});
