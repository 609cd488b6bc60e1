// Properties of resuming from an LMS (readResume.js): cmi.suspend_data is whatever the LMS hands
// back, so it may be cut short, edited, kept by an older version of the page, any JSON or none,
// or far longer than SCORM 1.2's 4096 characters. Whatever it holds, reading it never throws,
// gives answers valid for the sheet or none, and says what it refused in a plain sentence.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { SUSPEND_LIMIT, readResume } from '../../src/homework/readResume.js';
import { QUESTIONS } from '../../src/homework/questions.js';
import { MAX_TYPED, questionParams, readAnswer } from '../../src/homework/gradeAnswer.js';
import { anyJson, anyText, anyValue } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

/** A sheet as the page sets it up: its questions (repeats allowed, up to 40), the seed, the class seed. */
const sheet = fc.tuple(fc.array(fc.constantFrom(...QUESTIONS), { minLength: 1, maxLength: 40 }), fc.string({ minLength: 1, maxLength: 64 }), fc.boolean())
  .map(([questions, seed, fromClass]) => ({ questions, seed, classSeed: fromClass ? seed : null, params: questions.map((q) => questionParams(q, seed)) }));

/** An answer the card can record for a question, or none. */
const answerFor = (question, params) => fc.option(question.kind === 'choice' ? fc.constantFrom(...question.options(params).map((o) => o.id))
  : question.kind === 'predict' ? fc.integer({ min: 0, max: 900 }).map((t) => t / 10)
    : fc.oneof(fc.double({ noNaN: true }).map(String), anyText).map((t) => readAnswer(question, params, t)), { nil: null });

/** A sheet with answers, and cmi.suspend_data as the page writes it (connectScorm's save). */
const saved = sheet.chain((s) => fc.tuple(...s.questions.map((q, i) => answerFor(q, s.params[i])))
  .map((answers) => ({ ...s, answers, text: JSON.stringify({ seed: s.seed, answers }) })));

// eslint-disable-next-line no-control-regex
const readable = (notice) => typeof notice === 'string' && /^[A-Z0-9][^{}"<>\u0000-\u001f]{20,300}\.$/.test(notice);

/** What the page may do with a reading: answers none or one per question, each valid for it; a notice a sentence. */
function expectUsable({ answers, notice }, { questions, params }) {
  if (answers !== null) {
    expect(answers).toHaveLength(questions.length);
    answers.forEach((a, i) => expect(a === null || readAnswer(questions[i], params[i], a) === a, JSON.stringify(a)).toBe(true));
  }
  expect(notice === null || readable(notice), notice).toBe(true);
}
const read = (text, s) => readResume(text, { seed: s.seed, classSeed: s.classSeed, questions: s.questions, params: s.params });

describe('resuming from cmi.suspend_data', () => {
  it('gives back what the page kept, without a word', () => {
    check(fc.property(saved, (s) => {
      fc.pre(s.text.length <= SUSPEND_LIMIT); // longer, the page does not keep it (and says so)
      expect(read(s.text, s)).toEqual({ answers: s.answers, notice: null });
    }), 200);
  });

  it('keeps a 40-question sheet within 4096 characters whenever its typed answers need no escaping in JSON', () => {
    const plain = fc.string({ unit: fc.constantFrom(...'0123456789.,-+e %°abcxyz'), minLength: 1, maxLength: MAX_TYPED });
    const full = fc.tuple(fc.array(fc.constantFrom(...QUESTIONS), { minLength: 40, maxLength: 40 }), fc.string({ unit: 'binary-ascii', minLength: 1, maxLength: 64 }))
      .chain(([questions, seed]) => fc.tuple(...questions.map((q) => {
        const params = questionParams(q, seed);
        if (q.kind === 'numeric') return plain.map((t) => readAnswer(q, params, t) ?? '0');
        return answerFor(q, params).map((a) => a ?? (q.kind === 'predict' ? 45.5 : q.options(params)[0].id));
      })).map((answers) => JSON.stringify({ seed, answers })));
    check(fc.property(full, (text) => { expect(text.length).toBeLessThanOrEqual(SUSPEND_LIMIT); }), 100);
  });

  it('never throws on whatever the LMS hands back, and gives answers valid for the sheet or none', () => {
    const anything = fc.oneof(
      anyText,
      fc.string({ unit: 'binary', maxLength: 200 }),
      anyJson.map((v) => JSON.stringify(v) ?? ''),
      fc.tuple(anyValue, anyValue).map(([seed, answers]) => JSON.stringify({ seed, answers }) ?? ''),
      fc.string({ maxLength: 6 }).map((t) => `${'['.repeat(3000)}${t}`),
      fc.constantFrom('null', '""', '[]', '{}', '{"answers":null}', '{"answers":{}}', '{"seed":null,"answers":[]}', ' ', '\u0000'),
    );
    check(fc.property(sheet, anything, (s, text) => expectUsable(read(text, s), s)), 400);
  });

  it('refuses a copy cut at any point, saying so unless nothing is left', () => {
    check(fc.property(saved.chain((s) => fc.nat({ max: s.text.length - 1 }).map((n) => [s, s.text.slice(0, n)])), ([s, cut]) => {
      const result = read(cut, s);
      expect(result.answers).toBeNull();
      expect(result.notice === null).toBe(cut.trim() === '');
      expectUsable(result, s);
    }), 300);
  });

  it('reads an edited copy (a character changed, added or taken out) into answers valid for the sheet, or refuses it', () => {
    const edit = fc.tuple(fc.nat(), fc.constantFrom('replace', 'insert', 'delete'), fc.string({ unit: 'binary', minLength: 1, maxLength: 1 }));
    check(fc.property(saved, edit, (s, [at, how, character]) => {
      const i = at % s.text.length;
      const text = s.text.slice(0, i) + (how === 'delete' ? '' : character) + s.text.slice(how === 'insert' ? i : i + 1);
      const result = read(text, s);
      expectUsable(result, s);
      if (text === s.text && text.length <= SUSPEND_LIMIT) expect(result.answers).toEqual(s.answers);
    }), 400);
  });

  it('takes any JSON in place of an answer: one that fits its question is kept, one that does not is left open and counted', () => {
    const shaped = sheet.chain((s) => fc.tuple(...s.questions.map((q, i) => fc.oneof(answerFor(q, s.params[i]), anyJson))).map((answers) => ({ ...s, answers })));
    check(fc.property(shaped, (s) => {
      const text = JSON.stringify({ seed: s.seed, answers: s.answers });
      fc.pre(text.length <= SUSPEND_LIMIT);
      const result = read(text, s);
      expectUsable(result, s);
      const back = JSON.parse(text).answers; // what the LMS holds: JSON's -0 is 0
      const fits = back.map((a, i) => a !== null && readAnswer(s.questions[i], s.params[i], a) === a);
      result.answers.forEach((a, i) => expect(a).toEqual(fits[i] ? back[i] : readAnswer(s.questions[i], s.params[i], back[i])));
      const open = result.answers.filter((a, i) => a === null && back[i] !== null).length;
      expect(result.notice === null).toBe(open === 0);
      if (open) expect(result.notice).toMatch(new RegExp(`^${open} of the answers`));
    }), 300);
  });

  it('reads a copy kept by the first version of the page (answers alone) only where the sheet\'s class seed made its numbers', () => {
    check(fc.property(saved, (s) => {
      const text = JSON.stringify({ answers: s.answers });
      fc.pre(text.length <= SUSPEND_LIMIT);
      const result = read(text, s);
      if (s.classSeed) expect(result).toEqual({ answers: s.answers, notice: null });
      else expect(result).toEqual({ answers: null, notice: expect.stringContaining('earlier version of this page') });
    }), 150);
  });

  it('refuses a copy for other numbers or another sheet, and one longer than SCORM 1.2 keeps, with a sentence', () => {
    check(fc.property(saved, fc.string({ minLength: 1, maxLength: 64 }), fc.integer({ min: 1, max: 3 }), (s, other, extra) => {
      fc.pre(other !== s.seed && s.text.length <= SUSPEND_LIMIT);
      const elsewhere = read(JSON.stringify({ seed: other, answers: s.answers }), s);
      expect(elsewhere).toEqual({ answers: null, notice: expect.stringContaining('other numbers') });
      const longer = read(JSON.stringify({ seed: s.seed, answers: [...s.answers, ...Array(extra).fill(null)] }), s);
      expect(longer.answers).toBeNull();
      expect(longer.notice).toContain(`for a sheet of ${s.answers.length + extra} questions`);
      const huge = read(s.text + ' '.repeat(SUSPEND_LIMIT), s);
      expect(huge).toEqual({ answers: null, notice: expect.stringContaining('longer than this page ever writes') });
      for (const result of [elsewhere, longer, huge]) expectUsable(result, s);
    }), 150);
  });
});
