// Properties of the host's value store (src/host/createValueStore.js) over any sequence of sets,
// some made while the panel redraws, from any source, with some keys locked: the values stay valid
// per the schema and are those of applying the same sets one by one, in the order they were made;
// the panel never redraws inside a redraw; each change that started outside a redraw reaches the
// listeners once, with every key it and the sets during its redraws changed.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { createValueStore } from '../../src/host/createValueStore.js';
import { applyParams } from '../../src/host/params.js';
import { schema, start } from './everyKindSchema.js';
import { anyKey, anyValue, ownObject } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';
import { validValues } from './validValues.js';

const names = Object.entries(schema).flatMap(([key, spec]) => [key, ...(spec.aliases ?? [])]);
const keyOf = (name) => (Object.hasOwn(schema, name) ? name : Object.keys(schema).find((key) => schema[key].aliases?.includes(name)));

/** Near what a spec takes (its ends, its options, odd spellings) or, now and then, anything at all. */
const near = (spec) => ({
  number: () => fc.oneof(fc.double({ min: spec.min - 0.5, max: spec.max + 0.5, noNaN: true }), fc.constantFrom(spec.min, spec.max)),
  enum: () => fc.constantFrom(...spec.options, 'other'),
  color: () => fc.stringMatching(/^#?[0-9a-fA-F]{6}$/),
  boolean: () => fc.constantFrom(true, false, 'true', '0', 'maybe'),
  text: () => fc.string({ maxLength: 12 }),
}[spec.type]());
const rawFor = (spec) => fc.oneof({ weight: 4, arbitrary: near(spec) }, { weight: 1, arbitrary: anyValue });

const update = fc.array(
  fc.oneof({ weight: 4, arbitrary: fc.constantFrom(...names) }, { weight: 1, arbitrary: anyKey })
    .chain((name) => fc.tuple(fc.constant(name), keyOf(name) ? rawFor(schema[keyOf(name)]) : anyValue)),
  { maxLength: 4 },
).map(ownObject);

const source = fc.constantFrom('user', 'api', 'page');

/** A set, and the sets the panel makes during the redraw it causes (`deeper` levels of them). */
const step = (deeper) => fc.record({
  update,
  source,
  during: deeper ? fc.oneof(fc.constant([]), fc.array(step(deeper - 1), { minLength: 1, maxLength: 2 })) : fc.constant([]),
});

describe('the value store', () => {
  it('after any sets, re-entrant or locked, holds valid values: those of the same sets applied one by one', () => {
    const locks = fc.subarray(Object.keys(schema), { maxLength: 2 });
    check(fc.property(fc.array(step(2), { maxLength: 6 }), locks, (steps, locked) => {
      const made = []; // every set in the order it was made
      const pending = []; // the sets each redraw is to make, for the redraw next to run
      let depth = 0;
      const changes = [];
      const store = createValueStore('test', schema, start, {
        isLocked: (key) => locked.includes(key),
        redraw() {
          expect(depth).toBe(0);
          depth += 1;
          for (const inner of pending.shift()?.during ?? []) run(inner);
          depth -= 1;
        },
      });
      store.onChange((change) => changes.push(change));
      const run = ({ update: u, source: s, during }) => {
        made.push([u, s]);
        // What this set's redraw is to make: it comes now (none running) or after the running one.
        const plan = { during };
        pending.push(plan);
        const { changed } = store.set(u, { source: s });
        if (!changed.length && pending.includes(plan)) pending.splice(pending.indexOf(plan), 1); // no redraw for it
        return changed;
      };

      for (const outer of steps) {
        const before = { ...store.values };
        const heard = changes.length;
        const changed = run(outer);
        pending.length = 0; // a set whose redraw was one with another's makes nothing more
        if (!changed.length) {
          expect(changes.length).toBe(heard);
          continue;
        }
        // One listener call, with every key whose value the change and its redraws' sets touched.
        expect(changes.length).toBe(heard + 1);
        const { keys, source: heardSource } = changes.at(-1);
        expect(heardSource).toBe(outer.source);
        expect(new Set(keys).size).toBe(keys.length);
        expect(keys.every((key) => Object.hasOwn(schema, key))).toBe(true);
        expect(keys).toEqual(expect.arrayContaining(Object.keys(schema).filter((key) => !Object.is(before[key], store.values[key]))));
      }

      // The same sets, one by one, with the lock rule written out here.
      const expected = { ...start };
      for (const [u, s] of made) {
        const touchesLocked = s !== 'api' && Object.keys(u).some((name) => locked.includes(keyOf(name)));
        if (!touchesLocked) applyParams(schema, expected, u);
      }
      expect({ ...store.values }).toEqual(expected);
      expect(validValues(schema, store.values)).toBe(true);
    }), 200);
  });
});
