// Properties of the homework layer's doors for sheets and hand-ins: a sheet read from JSON
// (readSheet.js), sheets and hand-ins as codes (sheetCodes.js), and grading by recomputation
// (gradeHandIn.js, gradeAnswer.js). Everything read here comes from outside: a lecturer's file, a
// student's hand-in, a link an LMS or a mail program passed on.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { readSheet } from '../../src/homework/readSheet.js';
import { handInFromText, handInToCode, makeHandIn, sheetFromCode, sheetToCode } from '../../src/homework/sheetCodes.js';
import { gradeHandIn, sheetFingerprint } from '../../src/homework/gradeHandIn.js';
import { QUESTIONS, questionById } from '../../src/homework/questions.js';
import { gradeAnswer, questionParams, trueOption } from '../../src/homework/gradeAnswer.js';
import { formatValue } from '../../src/homework/formatAnswer.js';
import { EMBED_KEYS } from '../../src/host/readEmbedOptions.js';
import { clipText, parseValue, rawText, resolveKey } from '../../src/host/params.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { anyJson, anyKey, anyText, anyValue } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const reasons = (problems) => Array.isArray(problems) && problems.length > 0 && problems.every((p) => typeof p === 'string' && /\S/.test(p));
const SHEET_FIELDS = ['version', 'title', 'reveal', 'seed', 'lang', 'items'];
/** The languages a sheet may carry: the lab's (src/i18n/languages.js) and its pseudo-locales. */
const SHEET_LANGUAGES = ['en', 'es', 'en-XA', 'ar-XB'];
/** Whether every text in a value, keys included, is whole Unicode (no half of a surrogate pair). */
const wellFormed = (v) => (typeof v === 'string' ? v.isWellFormed()
  : v !== null && typeof v === 'object' ? Object.entries(v).every(([k, x]) => k.isWellFormed() && wellFormed(x)) : true);
/** Long text of characters beyond the BMP and combining marks: a reason that quotes it must not cut one in half. */
const longUnicode = fc.tuple(fc.string({ maxLength: 3 }), fc.string({ unit: 'grapheme', minLength: 12, maxLength: 40 })).map(([a, b]) => a + b);
const setOwn = (object, key, value) => Object.defineProperty(object, key, { value, enumerable: true, writable: true, configurable: true });

/** A start-state value a sheet keeps and the panel takes (readSheet keeps texts of up to 64 characters). */
const stateValue = (spec) => ({
  number: () => (spec.integer ? fc.integer({ min: spec.min, max: spec.max }) : fc.double({ min: spec.min, max: spec.max, noNaN: true }).map((v) => v + 0)),
  enum: () => fc.constantFrom(...(Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options))),
  color: () => fc.stringMatching(/^#[0-9a-f]{6}$/),
  boolean: () => fc.boolean(),
  text: () => fc.string({ unit: 'grapheme', minLength: 1, maxLength: 20 }).filter((t) => t.length <= 64 && parseValue(spec, t).ok),
}[spec.type]());

/** A start state for a panel: some of its keys (or their aliases) with values it takes. */
const stateFor = (panel) => {
  const names = Object.entries(panelSchema(panel)).flatMap(([key, spec]) => [key, ...(spec.aliases ?? [])].map((name) => [name, spec]))
    .filter(([name]) => !EMBED_KEYS.includes(name));
  return fc.uniqueArray(fc.constantFrom(...names), { selector: ([name]) => name, maxLength: 4 })
    .chain((picked) => fc.tuple(...picked.map(([name, spec]) => stateValue(spec).map((v) => [name, v]))))
    .map((entries) => Object.fromEntries(entries));
};

const item = fc.constantFrom(...QUESTIONS).chain((q) => fc.option(stateFor(q.panel), { nil: undefined })
  .map((state) => (state ? { question: q.id, state } : { question: q.id })));
const title = fc.oneof(anyText, fc.string({ unit: 'grapheme', minLength: 1, maxLength: 40 })).filter((t) => text(t, 200));
const seed = fc.oneof(anyText, fc.string({ unit: 'grapheme', minLength: 1, maxLength: 12 })).filter((t) => text(t, 64));

/** A sheet as a lecturer composes or writes one, from the real question bank and panel schemas. */
const sheet = fc.record({
  version: fc.constant(1), title, reveal: fc.constantFrom('after-answer', 'lecturer'), seed,
  lang: fc.constantFrom(...SHEET_LANGUAGES), items: fc.array(item, { minLength: 1, maxLength: 4 }),
}, { requiredKeys: ['version', 'title', 'items'] });

/** The sheet with one thing changed: a field replaced, or an own key (__proto__ among them) added somewhere. */
const edited = fc.tuple(sheet, fc.constantFrom('top', 'item', 'state', 'question', 'replace'), fc.oneof(anyKey, longUnicode), fc.oneof(anyJson, longUnicode)).map(([s, where, key, value]) => {
  const copy = structuredClone(s);
  const first = copy.items[0];
  if (where === 'top') setOwn(copy, key, value);
  else if (where === 'item') setOwn(first, key, value);
  else if (where === 'state') first.state = setOwn({ ...first.state }, key, value);
  else if (where === 'question') first.question = value;
  else copy[SHEET_FIELDS[key.length % SHEET_FIELDS.length]] = value;
  return copy;
});

/** What readSheet promises of a sheet it accepts. */
function expectValidSheet(s) {
  expect(Object.keys(s).every((k) => SHEET_FIELDS.includes(k))).toBe(true);
  expect(s.version).toBe(1);
  expect(text(s.title, 200)).toBe(true);
  expect(['after-answer', 'lecturer']).toContain(s.reveal);
  expect(s.seed === undefined || text(s.seed, 64)).toBe(true);
  expect(s.lang === undefined || SHEET_LANGUAGES.includes(s.lang)).toBe(true);
  expect(s.items.length >= 1 && s.items.length <= 40).toBe(true);
  for (const it of s.items) {
    const question = questionById(it.question);
    expect(question).toBeDefined();
    expect(Object.keys(it).every((k) => k === 'question' || k === 'state')).toBe(true);
    if (it.state === undefined) continue;
    expect(isObject(it.state)).toBe(true);
    for (const [key, value] of Object.entries(it.state)) {
      expect(EMBED_KEYS).not.toContain(key);
      expect(resolveKey(panelSchema(question.panel), key), key).toBeDefined();
      // Values are only shaped here: the panel checks each against its schema and says so on screen.
      expect((typeof value === 'number' && Number.isFinite(value)) || typeof value === 'boolean' || text(value, 64)).toBe(true);
    }
  }
}

describe('a sheet read from JSON', () => {
  it('any data is a valid sheet that reads as itself again, or refused with reasons that name an unknown id or key', () => {
    check(fc.property(fc.oneof(anyValue, anyJson, sheet, edited), (data) => {
      const read = readSheet(data);
      // What should be named: a question id the bank lacks, a field a sheet or an item does not have.
      const items = isObject(data) && Array.isArray(data.items) && data.items.length <= 40 ? data.items : [];
      const named = [
        ...items.filter((it) => !questionById(it?.question)).map((it) => rawText(it?.question)),
        ...(isObject(data) ? Object.keys(data).filter((k) => !SHEET_FIELDS.includes(k)) : []),
        ...(isObject(data) && data.lang !== undefined && !SHEET_LANGUAGES.includes(data.lang) ? [rawText(data.lang, 32)] : []),
        ...items.flatMap((it) => (isObject(it) ? Object.keys(it).filter((k) => k !== 'question' && k !== 'state') : [])),
        ...items.flatMap((it) => {
          const question = questionById(it?.question);
          const keys = question && isObject(it.state) ? Object.keys(it.state) : [];
          return keys.length > 24 ? [] : keys.filter((k) => resolveKey(panelSchema(question.panel), k) === undefined);
        }),
      ];
      if (read.ok) {
        expect(named).toEqual([]);
        expectValidSheet(read.sheet);
        expect(readSheet(read.sheet)).toEqual(read);
        return;
      }
      expect(reasons(read.problems)).toBe(true);
      if (wellFormed(data)) expect(read.problems.every((p) => p.isWellFormed())).toBe(true);
      const all = read.problems.join('\n');
      for (const name of named) expect(all).toContain(clipText(name, 32));
    }), 300);
  });

  it('a sheet composed from the question bank is accepted as written', () => {
    check(fc.property(sheet, (s) => {
      expect(readSheet(s)).toEqual({ ok: true, sheet: { reveal: 'after-answer', ...s } });
    }), 100);
  });
});

describe('sheet codes', () => {
  it('sheet → code → sheet is the same sheet, in characters a link keeps', () => {
    check(fc.property(sheet, (s) => {
      const read = readSheet(s);
      const code = sheetToCode(read.sheet);
      expect(code).toMatch(/^[A-Za-z0-9_-]+$/);
      const back = sheetFromCode(code);
      expect(back).toEqual({ ok: true, data: read.sheet });
      expect(readSheet(back.data)).toEqual(read);
    }), 150);
  });

  it('a code wrapped by a mail program reads the same; one cut short is refused with a reason', () => {
    const space = fc.constantFrom(' ', '\n', '\r\n', '\t', '\u00a0', '\u2028', '\n   ');
    check(fc.property(sheet, fc.array(fc.tuple(fc.nat(), space), { maxLength: 6 }), fc.nat(), (s, breaks, cut) => {
      const code = sheetToCode(s);
      let wrapped = code;
      for (const [at, gap] of breaks) wrapped = wrapped.slice(0, at % (wrapped.length + 1)) + gap + wrapped.slice(at % (wrapped.length + 1));
      expect(sheetFromCode(wrapped)).toEqual(sheetFromCode(code));
      expect(sheetFromCode(`\n${code}==\n`)).toEqual(sheetFromCode(code));
      const short = sheetFromCode(code.slice(0, cut % code.length));
      expect(short.ok).toBe(false);
      expect(reasons(short.problems)).toBe(true);
    }), 150);
  });

  // A code carries no check digits: about one change in twenty gives other data that is still a
  // sheet (a title one letter off). What holds is that nothing throws and readSheet judges the rest.
  it('a code with characters changed never throws: refused with a reason, or data that readSheet judges', () => {
    const change = fc.tuple(fc.nat(), fc.oneof(fc.constantFrom(...'AZaz09-_+/=.%*'), fc.string({ unit: 'binary', minLength: 1, maxLength: 2 })));
    check(fc.property(sheet, fc.array(change, { minLength: 1, maxLength: 3 }), (s, changes) => {
      let code = sheetToCode(s);
      for (const [at, by] of changes) code = code.slice(0, at % code.length) + by + code.slice((at % code.length) + 1);
      const back = sheetFromCode(code);
      if (!back.ok) return void expect(reasons(back.problems)).toBe(true);
      const read = readSheet(back.data);
      if (read.ok) expectValidSheet(read.sheet);
      else expect(reasons(read.problems)).toBe(true);
    }), 200);
  });

  it('any value given as a code is read or refused with reasons, never thrown on', () => {
    check(fc.property(fc.oneof(anyValue, anyText.map((t) => `FLH1.${t}`), anyText.map((t) => `{${t}`)), (raw) => {
      for (const read of [sheetFromCode(raw), handInFromText(raw)]) {
        expect(read.ok ? 'data' in read : reasons(read.problems)).toBe(true);
      }
    }), 300);
  });
});

/** Answers near what each question takes (its true option, its printed value, any angle) or anything at all. */
const answerFor = (question, params) => {
  const near = question.kind === 'choice'
    ? fc.constantFrom(...question.options(params).map((o) => o.id))
    : fc.oneof(fc.constant(formatValue(question, question.expected(params))), fc.double({ min: -10, max: 100 }), fc.double().map(String));
  return fc.oneof(near, near.map((value) => ({ value })), anyJson);
};

/** A hand-in as a student's page makes it, for a sheet from the question bank. */
const handIn = fc.tuple(sheet, seed, fc.oneof(fc.constant(''), anyText)).chain(([s, classSeed, name]) => {
  const read = readSheet(s).sheet;
  const studentSeed = read.seed ?? classSeed;
  const answers = read.items.map((it) => {
    const question = questionById(it.question);
    return answerFor(question, questionParams(question, studentSeed));
  });
  return fc.record({ answers: fc.tuple(...answers), attempts: fc.array(fc.oneof(fc.nat(9), anyJson), { minLength: answers.length, maxLength: answers.length }) })
    .map(({ answers: a, attempts }) => makeHandIn({ sheet: read, seed: studentSeed, name, answers: a, attempts, time: '2026-12-02T10:00:00.000Z' }));
});

/** As JSON keeps it: -0 is 0 there, and a file or a code is JSON. */
const asJson = (value) => JSON.parse(JSON.stringify(value));

describe('hand-ins', () => {
  it('hand-in → code → hand-in and hand-in → JSON → hand-in are the same, and grade the same', () => {
    check(fc.property(handIn, (h) => {
      const data = asJson(h);
      const code = handInToCode(data);
      expect(code.slice(5)).toMatch(/^[A-Za-z0-9_-]+$/);
      expect(handInFromText(`  ${code}\n`)).toEqual({ ok: true, data });
      expect(handInFromText(code.replace(/(.{50})/g, '$1\n'))).toEqual({ ok: true, data });
      expect(handInFromText(JSON.stringify(data, null, 2))).toEqual({ ok: true, data });
      expect(gradeHandIn(handInFromText(code).data)).toEqual(gradeHandIn(data));
    }), 40);
  });

  it('any answers grade without throwing: a score from 0 to the number of questions, and a correct answer is an answered one', () => {
    const anyAnswers = handIn.chain((h) => fc.array(anyValue, { minLength: h.answers.length, maxLength: h.answers.length })
      .map((answers) => ({ ...h, answers })));
    check(fc.property(fc.oneof(handIn, anyAnswers), (h) => {
      const graded = gradeHandIn(h);
      expect(graded.ok).toBe(true);
      expect(graded.total).toBe(h.sheet.items.length);
      expect(graded.score).toBe(graded.results.filter((r) => r.correct).length);
      expect(graded.score >= 0 && graded.score <= graded.total).toBe(true);
      for (const r of graded.results) expect(!r.correct || r.answered).toBe(true);
      // Through a code and back: what JSON cannot hold (undefined, NaN, -0) grades as it did.
      const back = handInFromText(handInToCode(h));
      expect(back.ok).toBe(true);
      expect(gradeHandIn(back.data).results.map((r) => r.correct)).toEqual(graded.results.map((r) => r.correct));
      expect(gradeHandIn(h, { expected: readSheet(h.sheet).sheet })).toEqual(graded);
    }), 40);
  });

  it('a score, a total or a "correct" the file carries is never read', () => {
    check(fc.property(handIn, anyValue, fc.boolean(), (h, claimed, flag) => {
      const tampered = {
        ...h, score: claimed, total: claimed, correct: claimed, results: claimed,
        answers: h.answers.map((a) => (typeof a === 'string' || typeof a === 'number' ? { value: a, correct: flag, score: claimed }
          : isObject(a) ? setOwn({ ...a }, 'correct', flag) : a)),
      };
      const before = gradeHandIn(h);
      const after = gradeHandIn(tampered);
      expect([after.score, after.total]).toEqual([before.score, before.total]);
      expect(after.results.map((r) => r.correct)).toEqual(before.results.map((r) => r.correct));
    }), 40);
  });

  it('any file, or a hand-in with one field replaced, is graded or refused with reasons, never thrown on', () => {
    const field = fc.constantFrom('kind', 'version', 'sheet', 'seed', 'name', 'answers', 'attempts', 'time', '__proto__', 'constructor');
    const damaged = fc.tuple(handIn, field, anyJson).map(([h, key, value]) => setOwn({ ...h }, key, value));
    check(fc.property(fc.oneof(anyValue, anyJson, damaged), fc.option(sheet.map((s) => readSheet(s).sheet)), (data, expected) => {
      const graded = gradeHandIn(data, { expected });
      if (!graded.ok) return void expect(reasons(graded.problems)).toBe(true);
      expect(graded.score >= 0 && graded.score <= graded.total).toBe(true);
      // Given the sheet that was set, a file for any other sheet is refused.
      if (expected) expect(graded.fingerprint).toBe(sheetFingerprint(expected));
    }), 100);
  });
});

describe('the question bank', () => {
  it('for any seed: a start state its panel takes, one true option or a finite expected value, and the printed answer graded right', () => {
    check(fc.property(fc.constantFrom(...QUESTIONS), seed, anyValue, (question, s, answer) => {
      const params = questionParams(question, s);
      const schema = panelSchema(question.panel);
      for (const [key, value] of Object.entries(question.state(params))) {
        expect(Object.hasOwn(schema, key), `${question.id} ${key}`).toBe(true);
        expect(parseValue(schema[key], value), `${question.id} ${key}`).toEqual({ ok: true, value });
      }
      if (question.kind === 'choice') {
        const right = trueOption(question, params);
        for (const option of question.options(params)) {
          expect(gradeAnswer(question, params, option.id).correct).toBe(option.id === right.id);
          expect(option.why(params)).toMatch(/\S/);
        }
      } else {
        const expected = question.expected(params);
        expect(Number.isFinite(expected)).toBe(true);
        if (question.kind === 'predict') expect(expected >= 0 && expected <= 90).toBe(true);
        expect(gradeAnswer(question, params, formatValue(question, expected)).correct, question.id).toBe(true);
      }
      const graded = gradeAnswer(question, params, answer);
      expect(!graded.correct || graded.answered).toBe(true);
      expect(graded.explanation).toMatch(/\S/);
    }), 120);
  });
});

describe('what these properties found', () => {
  const base = { version: 1, title: 'T', items: [{ question: 'exact-r' }] };
  it('a field a sheet or an item does not have is named, not dropped: a typo would lose a start state unseen', () => {
    expect(readSheet({ ...base, items: [{ question: 'exact-r', stat: { theta: 10 } }] }))
      .toEqual({ ok: false, problems: ['item 1: “stat” is not a field of an item (question, state).'] });
    expect(readSheet({ ...base, due: 'Friday' }))
      .toEqual({ ok: false, problems: ['“due” is not a field of a sheet (version, title, reveal, seed, lang, items).'] });
  });
  it('a code that is no text is refused, and a quoted id never ends in half a character', () => {
    const hostile = JSON.parse('{"toString":1}');
    expect(sheetFromCode(hostile)).toEqual({ ok: false, problems: ['No sheet link was given.'] });
    expect(handInFromText(hostile).ok).toBe(false);
    expect(readSheet({ ...base, items: [{ question: `${'x'.repeat(39)}😀` }] }).problems).toEqual([`item 1: there is no question “${'x'.repeat(39)}…”.`]);
  });
});
