// Keys and values from outside (a sheet, a hand-in, a start state, a link) that name something
// every object inherits, or whose toString is not a function, are refused by name, never thrown on.
import { describe, expect, it } from 'vitest';
import { readSheet } from '../../src/homework/readSheet.js';
import { gradeHandIn } from '../../src/homework/gradeHandIn.js';
import { makeHandIn } from '../../src/homework/sheetCodes.js';
import { readStartState } from '../../src/homework/readStartState.js';
import { parseValue } from '../../src/host/params.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { isObject, own } from '../../src/host/own.js';

const INHERITED = ['constructor', 'toString', 'valueOf', 'hasOwnProperty', '__proto__', '__defineGetter__', 'isPrototypeOf'];
const sheet = { version: 1, title: 'T', items: [{ question: 'exact-r' }] };

describe('a sheet', () => {
  it('whose question id is an object with a toString that is no function is refused, not thrown on', () => {
    const data = JSON.parse('{"version":1,"title":"T","items":[{"question":{"toString":1}}]}');
    expect(readSheet(data)).toEqual({ ok: false, problems: ['item 1: there is no question “(an object)”.'] });
  });
  it('whose start state names a value its panel does not have is refused by that name', () => {
    for (const name of ['constructor', 'toString', 'valueOf', 'isPrototypeOf', 'thetaa']) {
      const read = readSheet({ ...sheet, items: [{ question: 'exact-r', state: JSON.parse(`{"${name}":1}`) }] });
      expect(read, name).toEqual({ ok: false, problems: [`item 1: ${name} is not a value of this question's panel.`] });
    }
    expect(readSheet({ ...sheet, items: [{ question: 'exact-r', state: { theta: 10 } }] }).ok).toBe(true);
  });
});

describe('a hand-in', () => {
  it('whose seed is an object with a toString that is no function is refused, not thrown on', () => {
    const handIn = { ...makeHandIn({ sheet: { ...sheet, seed: 'class' }, seed: 'x', answers: [null] }), seed: JSON.parse('{"toString":1}') };
    const graded = gradeHandIn(handIn);
    expect(graded.ok).toBe(false);
    expect(graded.problems).toContain('this sheet gives everyone the seed class, but the file says (an object).');
  });
});

describe('a start state', () => {
  it('names each key its panel does not have, inherited names included', () => {
    for (const name of INHERITED) {
      expect(readStartState(`${encodeURIComponent(name)}=1&theta=10`, 'exact-fresnel'), name)
        .toEqual({ ok: false, problem: `${name} is not a value of the “Reflection math: the exact formula” panel.` });
    }
  });
  it('keeps the panel\'s own keys, an alias under its key, and reads numbers only as decimals', () => {
    expect(readStartState('camEl=10&fresnel=false', 'asphalt')).toEqual({ ok: true, state: { camEl: 10, fresnel: false } });
    expect(readStartState('n1=1.2', 'polarization')).toEqual({ ok: true, state: { nI: 1.2 } });
    expect(readStartState('theta=0x1', 'exact-fresnel')).toEqual({ ok: false, problem: 'theta=0x1 is not a number.' });
  });
});

describe('a number in a link or a message', () => {
  it('is decimal: hex, binary, octal and Infinity are refused', () => {
    const spec = { type: 'number', default: 1, min: -1e9, max: 1e9, step: 1, label: 'x' };
    for (const raw of ['0x1', '0b1', '0o7', 'Infinity', '1_000', '1,5', '', ' ', '1e', '.', '+-1']) expect(parseValue(spec, raw).ok, raw).toBe(false);
    for (const [raw, value] of [[' 1 ', 1], ['1e3', 1000], ['.5', 0.5], ['2.', 2], ['+3', 3], ['-1E2', -100]]) expect(parseValue(spec, raw), raw).toEqual({ ok: true, value });
  });
});

describe('panel schemas by id', () => {
  it('find a panel\'s schema, and nothing for an inherited name', () => {
    expect(Object.keys(panelSchema('schlick'))).toContain('nT');
    for (const name of INHERITED) expect(panelSchema(name), name).toBeUndefined();
  });
});

describe('own and isObject (src/host/own.js), which every reader of outside data uses', () => {
  it('read an own key only: an inherited name is absent, and a JSON __proto__ key is data', () => {
    for (const name of INHERITED) expect(own({}, name), name).toBeUndefined();
    expect(own(JSON.parse('{"__proto__":1,"constructor":2}'), '__proto__')).toBe(1);
    expect(own(JSON.parse('{"__proto__":1,"constructor":2}'), 'constructor')).toBe(2);
    expect(own({ kind: 'x' }, 'kind')).toBe('x');
  });
  it('find no keys in what is no object: null, a list, a text, a number', () => {
    for (const value of [null, undefined, [1], 'abc', 3, true]) {
      expect(isObject(value), String(value)).toBe(false);
      expect(own(value, value === 'abc' ? 'length' : '0'), String(value)).toBeUndefined();
    }
    expect(isObject({}) && isObject(Object.create(null))).toBe(true);
  });
});
