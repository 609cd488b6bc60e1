// Views a panel can hold, as fast-check arbitraries over each panel's schema: what a control or a
// deck would set, on the grid a link writes (a number to its step).
import fc from 'fast-check';
import { readdirSync } from 'node:fs';
import { parseValue } from '../../src/host/params.js';
import { PANELS } from '../../src/panels/manifest.js';

const ids = readdirSync(new URL('../../src/panels/', import.meta.url)).filter((d) => PANELS.some((p) => p.id === d));
/** [id, schema] of every panel. */
export const schemas = await Promise.all(ids.map(async (id) => [id, (await import(`../../src/panels/${id}/schema.js`)).schema]));

/** A valid value for a spec, drawn as a control or a deck would make it. */
export const validFor = (spec) => ({
  number: () => (spec.integer ? fc.integer({ min: spec.min, max: spec.max })
    : fc.oneof(fc.integer({ min: Math.round(spec.min / spec.step), max: Math.round(spec.max / spec.step) })
      .map((i) => Number((i * spec.step).toFixed(12))).filter((v) => v >= spec.min && v <= spec.max),
    fc.constantFrom(spec.min, spec.max, spec.default))),
  enum: () => fc.constantFrom(...(Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options))),
  color: () => fc.stringMatching(/^#[0-9a-f]{6}$/),
  boolean: () => fc.boolean(),
  text: () => fc.string({ unit: 'grapheme', maxLength: 80 }).map((t) => parseValue(spec, t)).filter((r) => r.ok).map((r) => r.value),
}[spec.type]());

/** A whole view of a panel: a valid value for each key of its schema. */
export const validView = (schema) => fc.record(Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, validFor(spec)])));

/** A panel's schema and something drawn for it: one property covers every panel. */
export const forAnyPanel = (make) => fc.constantFrom(...schemas).chain(([id, schema]) => fc.tuple(fc.constant(id), fc.constant(schema), make(schema)));
