// Properties of what the homework pages read as text or find in the browser: a start state a
// lecturer pastes for a panel (readStartState.js), a typed answer with its unit (parseAnswer.js),
// and a student's work kept in localStorage (answerStore.js), which anyone can edit by hand.
import { afterEach, describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { readStartState } from '../../src/homework/readStartState.js';
import { parseAnswer } from '../../src/homework/parseAnswer.js';
import { openAnswerStore } from '../../src/homework/page/answerStore.js';
import { EMBED_KEYS } from '../../src/host/readEmbedOptions.js';
import { formatValue, parseValue, rawText, resolveKey } from '../../src/host/params.js';
import { PANEL_IDS, lecturePrefix } from '../../src/panels/manifest.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { PROTOTYPE_NAMES, anyJson, anyKey, anyNumber, anyText, anyValue } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

/** Whether a start-state value is one the panel takes as it is (texts as the link writes them). */
function valid(spec, value) {
  const read = parseValue(spec, value);
  if (!read.ok) return false;
  return spec.type === 'text' ? typeof value === 'string' : Object.is(read.value, value);
}

/** A panel id: every real one, and ids no panel has. */
const panelId = fc.oneof({ weight: 4, arbitrary: fc.constantFrom(...PANEL_IDS) }, { weight: 1, arbitrary: fc.constantFrom(...PROTOTYPE_NAMES, 'no-such-panel', '', 'spheres.') });

/** A raw value for a key: near what its spec takes, a value written as a link writes it, or anything. */
const rawFor = (spec) => {
  const near = spec ? {
    number: () => fc.oneof(fc.double({ min: spec.min, max: spec.max, noNaN: true }).map((v) => formatValue(spec, v)), fc.constantFrom(`${spec.min}`, `${spec.max}`, `${spec.max + 1}`)),
    enum: () => fc.constantFrom(...(Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options))),
    color: () => fc.stringMatching(/^#?[0-9a-fA-F]{6}$/),
    boolean: () => fc.constantFrom('true', 'false', '1', '0', 'yes'),
    text: () => fc.string({ unit: 'grapheme', maxLength: 30 }),
  }[spec.type]() : anyText;
  return fc.oneof(near, anyText);
};

/** key=value pairs for a panel: its keys and aliases, embed options, names it lacks, odd values. */
const pairsFor = (id) => {
  const schema = panelSchema(id) ?? {};
  const names = Object.entries(schema).flatMap(([key, spec]) => [key, ...(spec.aliases ?? [])]);
  const key = fc.oneof({ weight: 4, arbitrary: names.length ? fc.constantFrom(...names) : anyKey }, { weight: 1, arbitrary: anyKey });
  const pair = key.chain((k) => fc.tuple(fc.constant(k), rawFor(schema[resolveKey(schema, k)])));
  return fc.array(pair, { maxLength: 6 });
};

/** How the pairs reach the composer: bare, in an embed link, or in a lecture link with the panel's prefix. */
const FORMS = {
  bare: (id, pairs) => new URLSearchParams(pairs).toString(),
  embed: (id, pairs) => `https://example.org/lab/embed.html?${new URLSearchParams([['panel', id], ...pairs, ['theme', 'dark']])}`,
  lecture: (id, pairs) => `./index.html?${new URLSearchParams(pairs.map(([k, v]) => [lecturePrefix(id) + k, v]))}#${id}`,
};

describe('a start state from a link', () => {
  it('any text for any panel: a state of that panel\'s own keys and valid values, or a problem', () => {
    const input = panelId.chain((id) => fc.tuple(fc.constant(id), fc.oneof(anyText, anyValue,
      fc.tuple(fc.constantFrom(...Object.keys(FORMS)), pairsFor(id)).map(([form, pairs]) => FORMS[form](id, pairs)))));
    check(fc.property(input, ([id, text]) => {
      const read = readStartState(text, id);
      if (!read.ok) {
        expect(read.problem).toMatch(/\S/);
        if (typeof text === 'string' && text.isWellFormed()) expect(read.problem.isWellFormed()).toBe(true);
        return;
      }
      const schema = panelSchema(id) ?? {};
      for (const [key, value] of Object.entries(read.state)) {
        expect(Object.keys(schema), key).toContain(key);
        expect(valid(schema[key], value), `${key}=${value}`).toBe(true);
      }
    }), 300);
  });

  it('names every key its panel lacks and every value it refuses; takes the rest under the panel\'s own keys', () => {
    const input = fc.constantFrom(...PANEL_IDS).chain((id) => fc.tuple(fc.constant(id), fc.constantFrom(...Object.keys(FORMS)), pairsFor(id)));
    check(fc.property(input, ([id, form, given]) => {
      // The embed page's options and another panel's lecture keys are not the item's: they are left
      // out. A link holds Unicode text: half a surrogate pair reads back as U+FFFD.
      const pairs = given.map(([k, v]) => [k.toWellFormed(), v.toWellFormed()]).filter(([k]) => !EMBED_KEYS.includes(k) && !k.includes('.'));
      const schema = panelSchema(id);
      const offending = pairs.filter(([k, v]) => resolveKey(schema, k) === undefined || !parseValue(schema[resolveKey(schema, k)], v).ok).map(([k]) => k);
      const read = readStartState(FORMS[form](id, pairs), id);
      if (offending.length) {
        expect(read.ok).toBe(false);
        for (const k of offending) expect(read.problem).toContain(rawText(k));
        return;
      }
      const state = {};
      for (const [k, v] of pairs) {
        const key = resolveKey(schema, k);
        state[key] = schema[key].type === 'text' ? v : parseValue(schema[key], v).value;
      }
      expect(read).toEqual({ ok: true, state });
    }), 300);
  });

  it('a state written as a link reads back as the same state', () => {
    const stateOf = (id) => {
      const schema = panelSchema(id);
      return fc.subarray(Object.keys(schema)).chain((keys) => fc.tuple(...keys.map((k) => rawFor(schema[k]).map((raw) => [k, parseValue(schema[k], raw)]))))
        .map((entries) => Object.fromEntries(entries.filter(([, r]) => r.ok).map(([k, r]) => [k, schema[k].type === 'text' ? formatValue(schema[k], r.value) : r.value])));
    };
    // Text a link can carry: a lone surrogate (no character at all) is written by any URL as U+FFFD.
    const carried = (state) => Object.values(state).every((v) => typeof v !== 'string' || v.isWellFormed());
    const ids = fc.constantFrom(...PANEL_IDS);
    check(fc.property(ids.chain((id) => fc.tuple(fc.constant(id), stateOf(id).filter(carried))), ([id, state]) => {
      const schema = panelSchema(id);
      const link = new URLSearchParams(Object.entries(state).map(([k, v]) => [k, schema[k].type === 'text' ? v : formatValue(schema[k], v)])).toString();
      const read = readStartState(link, id);
      expect(read.ok).toBe(true);
      for (const [k, v] of Object.entries(state)) {
        if (schema[k].type === 'number') expect(Math.abs(read.state[k] - v)).toBeLessThanOrEqual(schema[k].step / 2 + 1e-12);
        else expect(read.state[k]).toEqual(v);
      }
    }), 200);
  });
});

describe('a typed answer', () => {
  it('any value with any unit is a finite number or refused with a reason, never thrown on', () => {
    const long = fc.tuple(fc.string({ maxLength: 3 }), fc.constantFrom('', '1 ', '-2,5'), fc.string({ unit: 'grapheme', minLength: 12, maxLength: 40 })).map((parts) => parts.join(''));
    check(fc.property(fc.oneof(anyValue, anyText, anyNumber, long), fc.constantFrom('deg', 'fraction', null, undefined), (raw, unit) => {
      const read = parseAnswer(raw, unit);
      if (read.ok) expect(Number.isFinite(read.value)).toBe(true);
      else expect(read.reason).toMatch(/\S/);
      // A reason quotes what was typed: never half a character.
      if (!read.ok && typeof raw === 'string' && raw.isWellFormed()) expect(read.reason.isWellFormed()).toBe(true);
    }), 300);
  });

  it('a number written with a point or a comma, and its unit, reads as that number', () => {
    const written = fc.tuple(fc.double({ min: -1e6, max: 1e6, noNaN: true }), fc.constantFrom('deg', 'fraction', null), fc.boolean(), fc.constantFrom('', ' ', '  '));
    check(fc.property(written, ([x, unit, comma, gap]) => {
      const digits = String(x).replace(/^-/, '−');
      const typed = comma && !digits.includes('e') ? digits.replace('.', ',') : digits;
      expect(parseAnswer(typed, unit)).toEqual({ ok: true, value: x + 0 });
      if (unit === 'deg') expect(parseAnswer(`${typed}${gap}°`, unit)).toEqual({ ok: true, value: x + 0 });
      if (unit === 'fraction') expect(parseAnswer(`${typed}${gap}%`, unit).value).toBeCloseTo(x / 100, 12);
    }), 200);
  });
});

describe('work kept in this browser', () => {
  const original = globalThis.window;
  afterEach(() => { globalThis.window = original; });

  /** What localStorage might hold: nothing, any text, JSON of any shape, or work edited by hand. */
  const held = fc.oneof(fc.constant(null), anyText, anyJson.map((v) => JSON.stringify(v)),
    fc.record({ seed: anyJson, name: anyJson, answeredWith: anyJson, answers: anyJson, attempts: fc.oneof(anyJson, fc.array(anyJson)) }, { requiredKeys: [] })
      .map((v) => JSON.stringify(v)));

  it('whatever storage holds, returns or throws, the work has its shape and saving never throws', () => {
    const storage = fc.record({ held, reads: fc.constantFrom('returns', 'throws', 'no storage', 'not text'), writes: fc.constantFrom('keeps', 'throws') });
    check(fc.property(storage, fc.nat(40), (s, count) => {
      const kept = new Map();
      globalThis.window = /** @type {any} */ (s.reads === 'no storage' ? {} : {
        localStorage: {
          getItem: (key) => {
            if (s.reads === 'throws') throw new Error('SecurityError');
            return kept.has(key) ? kept.get(key) : s.reads === 'not text' ? { toString: 'x' } : s.held;
          },
          setItem: (key, value) => { if (s.writes === 'throws') throw new Error('QuotaExceededError'); kept.set(key, value); },
        },
      });
      const store = openAnswerStore('sheet-code', count, () => 'fresh');
      const { work } = store;
      expect(typeof work.seed === 'string' && work.seed.length > 0 && work.seed.length <= 64).toBe(true);
      expect(typeof work.name === 'string' && work.name.length <= 100).toBe(true);
      expect(work.answeredWith === null || typeof work.answeredWith === 'string').toBe(true);
      expect(work.answers).toHaveLength(count);
      expect(work.attempts).toHaveLength(count);
      for (const n of work.attempts) expect(Number.isInteger(n) && n >= 0).toBe(true);
      expect(() => store.save()).not.toThrow();
      expect(() => store.forSeed('another')).not.toThrow();
      expect(work.answers.every((a) => a === null)).toBe(true);
      // Saved and opened again, the work is what it was (where the browser kept it).
      if (s.reads === 'returns' && s.writes === 'keeps') {
        expect(store.kept()).toBe(true);
        expect(openAnswerStore('sheet-code', count, () => 'other').work).toEqual(work);
      }
    }), 200);
  });
});

describe('what these properties found', () => {
  it('a start state\'s value its panel refuses is named; an alias is kept under its key; an unknown panel is no crash', () => {
    expect(readStartState('theta=abc', 'exact-fresnel')).toEqual({ ok: false, problem: 'theta=abc is not a number.' });
    expect(readStartState('n1=1.2', 'polarization')).toEqual({ ok: true, state: { nI: 1.2 } });
    expect(readStartState('x=1', 'no-such-panel')).toEqual({ ok: false, problem: 'x is not a value of the “no-such-panel” panel.' });
    expect(readStartState(JSON.parse('{"toString":1}'), 'schlick')).toEqual({ ok: true, state: {} });
  });
  it('a typed answer that is no text is no answer, and a quoted one never ends in half a character', () => {
    expect(parseAnswer(JSON.parse('{"toString":1}'))).toEqual({ ok: false, reason: 'No answer was given.' });
    expect(parseAnswer(`a${'😀'.repeat(30)}`).reason).toBe(`“a${'😀'.repeat(19)}” is not a number.`);
  });
});
