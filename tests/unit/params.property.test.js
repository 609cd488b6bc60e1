// Properties of every panel's link and values (src/host/params.js over each src/panels/*/schema.js):
// whatever a link or a message holds, reading it never throws, what is kept is valid against the
// schema, what is refused is named with a reason, and a view written to a link reads back the same.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { applyParams, defaults, describeProblem, formatValue, parseValue, readParams, resolveKey, writeParams } from '../../src/host/params.js';
import { anyKey, anyText, anyValue, ownObject } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';
import { validValues } from './validValues.js';
import { forAnyPanel, schemas, validView } from './schemaArbitraries.js';

/** A key a link or a message might use for this schema: its own, an alias, or anything else. */
const keyFor = (schema) => {
  const names = Object.entries(schema).flatMap(([key, spec]) => [key, ...(spec.aliases ?? [])]);
  return fc.oneof({ weight: 3, arbitrary: fc.constantFrom(...names) }, { weight: 2, arbitrary: anyKey });
};

/** A raw value near what this spec takes (its edges, its options, odd spellings) or anything. */
const rawFor = (spec) => {
  const near = {
    number: () => [fc.double({ min: spec.min, max: spec.max, noNaN: true }), fc.constantFrom(spec.min, spec.max, spec.min - 1e-9, spec.max + spec.step)],
    enum: () => [fc.constantFrom(...(Array.isArray(spec.options) ? spec.options : Object.keys(spec.options)))],
    color: () => [fc.stringMatching(/^#?[0-9a-fA-F]{6}$/)],
    boolean: () => [fc.constantFrom(true, false, 'true', 'false', '1', '0')],
    text: () => [fc.string({ unit: 'grapheme', maxLength: 60 })],
  }[spec.type]();
  return fc.oneof(...near, anyValue);
};

describe.each(schemas)('the %s panel\'s schema', (_id, schema) => {
  it('has defaults that it takes itself, written as no link at all', () => {
    expect(validValues(schema, defaults(schema))).toBe(true);
    expect(writeParams(schema, defaults(schema), new URLSearchParams()).toString()).toBe('');
  });
});

describe('every panel\'s link and values', () => {
  it('reads any query without throwing: each value kept is valid, each one refused is named with a reason', () => {
    const query = (schema) => fc.tuple(fc.constantFrom('', 'panel.'), fc.array(fc.tuple(keyFor(schema), anyText), { maxLength: 8 }));
    check(fc.property(forAnyPanel(query), ([id, schema, [prefix, pairs]]) => {
      const search = new URLSearchParams(pairs.map(([k, v]) => [prefix + k, v]));
      const { values, problems } = readParams(schema, search, prefix);
      expect(validValues(schema, values), id).toBe(true);
      for (const problem of problems) {
        expect(typeof problem.reason === 'string' && problem.reason.length > 0).toBe(true);
        expect(describeProblem(problem)).toMatch(/\S/);
      }
    }), 200);
  });

  it('takes any update without throwing: every key is applied or refused by name, and the values stay valid', () => {
    const update = (schema) => fc.oneof(
      fc.array(fc.tuple(keyFor(schema), fc.constantFrom(...Object.values(schema)).chain(rawFor)), { maxLength: 6 }).map(ownObject),
      anyValue);
    check(fc.property(forAnyPanel(update), ([id, schema, raw]) => {
      const values = defaults(schema);
      const { applied, rejected, changed } = applyParams(schema, values, raw);
      expect(validValues(schema, values), id).toBe(true);
      const named = raw !== null && typeof raw === 'object' ? Object.keys(raw) : [];
      for (const name of named) {
        const key = resolveKey(schema, name);
        const refused = rejected.some((r) => r.key === name);
        expect(refused || (key !== undefined && Object.hasOwn(applied, key)), name).toBe(true);
      }
      for (const r of rejected) {
        expect(r.reason).toMatch(/\S/);
        expect(describeProblem(r)).toContain(String(r.key).slice(0, 10));
      }
      expect(changed.every((key) => Object.hasOwn(schema, key))).toBe(true);
    }), 200);
  });

  it('a view written to a link reads back as the same view, and the link it writes is the same link', () => {
    check(fc.property(forAnyPanel(validView), ([id, schema, view]) => {
      const link = writeParams(schema, view, new URLSearchParams()).toString();
      const { values, problems } = readParams(schema, new URLSearchParams(link));
      expect(problems, id).toEqual([]);
      expect(values).toEqual(view);
      expect(writeParams(schema, values, new URLSearchParams()).toString()).toBe(link);
    }), 200);
  });

  it('any accepted value writes a link that reads back within half a step, and then stays put', () => {
    const one = (schema) => fc.constantFrom(...Object.keys(schema)).chain((key) => fc.tuple(fc.constant(key), rawFor(schema[key])));
    check(fc.property(forAnyPanel(one), ([id, schema, [key, raw]]) => {
      const spec = schema[key];
      const parsed = parseValue(spec, raw);
      if (!parsed.ok) return;
      const view = { ...defaults(schema), [key]: parsed.value };
      const link = writeParams(schema, view, new URLSearchParams()).toString();
      const { values, problems } = readParams(schema, new URLSearchParams(link));
      expect(problems, id).toEqual([]);
      if (spec.type === 'number') expect(Math.abs(values[key] - parsed.value)).toBeLessThanOrEqual(spec.step / 2 + 1e-12);
      else expect(values[key]).toEqual(parsed.value);
      expect(formatValue(spec, values[key])).toBe(formatValue(spec, parsed.value));
    }), 300);
  });
});
