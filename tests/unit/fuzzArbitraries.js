// What comes from outside, as fast-check arbitraries: names every object inherits, numbers at the
// ends of float64, NaN and friends spelled as text, Unicode that trips naive code, very long text,
// and objects whose toString is not a function (String() of one throws).
import fc from 'fast-check';

export const PROTOTYPE_NAMES = ['constructor', 'toString', 'valueOf', 'hasOwnProperty', '__proto__', '__defineGetter__',
  '__lookupGetter__', 'isPrototypeOf', 'propertyIsEnumerable', 'toLocaleString', 'prototype'];

export const ODD_NUMBERS = [NaN, Infinity, -Infinity, 1e308, -1e308, 5e-324, -5e-324, -0, 0, 1, -1, 0.5, 2 ** 53, Number.EPSILON];

export const ODD_TEXTS = ['NaN', 'nan', '+NaN', '-NaN', 'Infinity', '-Infinity', 'infinity', '1e999', '-1e999', '5e-324', '1e308',
  '-0', '0x1', '0b1', '0o7', ' 1 ', '1_000', '1,5', '1.', '.5', '+1', '--1', '', ' ', '\t', '\u0000', 'null', 'undefined',
  'true', 'TRUE', '1e', 'e1', 'e\u0301\u0301\u0301', '\u202eevil\u202c', '\u200f\u05d0\u05d1', '𝟙', '𝟙𝟚𝟛', '١٢٣', '１',
  '\ud800', '#GGGGGG', '#12345', 'ff8800', '*', '*1.', '*zzzzzz.AA', '%', '%zz', '&', '=', '?', '#', '<b>x</b>'];

/** A text of any kind: odd spellings, prototype names, any Unicode, now and then a very long one. */
export const anyText = fc.oneof(
  { weight: 3, arbitrary: fc.constantFrom(...ODD_TEXTS, ...PROTOTYPE_NAMES) },
  { weight: 3, arbitrary: fc.string({ unit: 'grapheme', maxLength: 20 }) },
  { weight: 2, arbitrary: fc.string({ unit: 'binary', maxLength: 20 }) },
  { weight: 1, arbitrary: fc.string({ maxLength: 8 }).map((s) => s.repeat(5000).slice(0, 20000)) },
);

/** A number of any kind: the ends of float64, NaN, ±0, and any double. */
export const anyNumber = fc.oneof(fc.constantFrom(...ODD_NUMBERS), fc.double(), fc.integer());

/** An object whose toString is not a function: String() of it throws. */
export const hostileObject = fc.constantFrom({ toString: 'x', valueOf: 1 }, JSON.parse('{"toString":1}'), Object.create(null));

/** A key from outside: a prototype name, an odd text, or any short text. */
export const anyKey = fc.oneof(fc.constantFrom(...PROTOTYPE_NAMES), anyText);

/** Any value a message, a JSON file or a link could carry (JSON.parse keeps __proto__ an own key). */
export const anyValue = fc.letrec((tie) => ({
  value: fc.oneof({ depthSize: 'small', withCrossShrink: true },
    anyNumber, anyText, fc.boolean(), fc.constant(null), fc.constant(undefined), hostileObject,
    fc.array(tie('value'), { maxLength: 4 }),
    fc.array(fc.tuple(anyKey, tie('value')), { maxLength: 4 }).map(ownObject)),
})).value;

/** An object with these entries as own keys, __proto__ included (as JSON.parse or a message makes it). */
export function ownObject(entries) {
  const object = {};
  for (const [key, value] of entries) Object.defineProperty(object, key, { value, enumerable: true, writable: true, configurable: true });
  return object;
}

/** JSON values only (what a file or a code holds), with prototype names among the keys. */
export const anyJson = fc.letrec((tie) => ({
  value: fc.oneof({ depthSize: 'small', withCrossShrink: true },
    fc.constantFrom(...ODD_NUMBERS).filter(Number.isFinite), fc.double({ noNaN: true, noDefaultInfinity: true }), anyText, fc.boolean(), fc.constant(null),
    fc.array(tie('value'), { maxLength: 4 }),
    fc.array(fc.tuple(anyKey, tie('value')), { maxLength: 4 }).map(ownObject)),
})).value;
