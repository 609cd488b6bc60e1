// Checked answers as SCORM 1.2 interactions (scormInteraction.js), and how the page's run-time
// connection journals them (connectScorm.js's record): next index from _count, the elements the LMS
// lists in _children, nothing at all where it keeps none.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { cmiDecimal, cmiString255, cmiTime, interactionId, scormInteraction } from '../../src/homework/scormInteraction.js';
import { QUESTIONS, questionById } from '../../src/homework/questions.js';
import { MAX_TYPED, questionParams, readAnswer, trueOption } from '../../src/homework/gradeAnswer.js';
import { decimalsFor } from '../../src/homework/formatAnswer.js';
import { connectScorm } from '../../src/homework/page/connectScorm.js';
import { anyText } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';
import { interactionProblems } from './scorm12Formats.js';

const SEED = 'lms-test';
const AT = new Date(2026, 2, 4, 9, 5, 7);
const setup = (id) => {
  const question = questionById(id);
  return { question, params: questionParams(question, SEED) };
};
const interaction = (id, answer, position = 3) => scormInteraction({ position, ...setup(id), answer, at: AT });

describe('an answer as an interaction', () => {
  it('a typed number is numeric, read as its value (a percentage as its fraction), the pattern to the decimals the question asks for', () => {
    const { question, params } = setup('exact-r');
    const R = question.expected(params);
    const typed = (100 * R).toFixed(2);
    const right = interaction('exact-r', `${typed} %`);
    expect(right).toEqual({
      id: 'q03-exact-r', type: 'numeric', student_response: expect.stringMatching(/^0\.\d{1,4}$/), result: 'correct', time: '09:05:07',
      'correct_responses.0.pattern': R.toFixed(decimalsFor(question)),
    });
    expect(Number(right.student_response)).toBeCloseTo(Number(typed) / 100, 12);
    expect(interaction('exact-r', (R + 0.01).toFixed(3))).toMatchObject({ type: 'numeric', student_response: (R + 0.01).toFixed(3), result: 'wrong' });
    expect(interaction('exact-r', '1,5')).toMatchObject({ student_response: '1.5', result: 'wrong' });
    expect(interaction('critical-angle', '41.8°')).toMatchObject({ type: 'numeric', student_response: '41.8' });
  });

  it('text that is no number, or in a unit the question does not take, is fill-in and unanticipated; a number no CMIDecimal spells is fill-in and wrong', () => {
    expect(interaction('exact-r', 'about half')).toMatchObject({ type: 'fill-in', student_response: 'about half', result: 'unanticipated' });
    expect(interaction('critical-angle', '41.8 km')).toMatchObject({ type: 'fill-in', student_response: '41.8 km', result: 'unanticipated' });
    const huge = interaction('toksvig-exponent', '1e30');
    expect(huge).toMatchObject({ type: 'fill-in', student_response: '1e30', result: 'wrong' });
    expect(huge['correct_responses.0.pattern']).toMatch(/^\d+\.\d+$/); // the right value is still a number
  });

  it('a prediction is numeric: the committed angle, against the true angle', () => {
    const { question, params } = setup('brewster-predict');
    const truth = question.expected(params);
    expect(interaction('brewster-predict', Math.round(truth * 10) / 10)).toMatchObject({
      type: 'numeric', student_response: String(Math.round(truth * 10) / 10), result: 'correct', 'correct_responses.0.pattern': truth.toFixed(2),
    });
    expect(interaction('brewster-predict', 0)).toMatchObject({ student_response: '0', result: 'wrong' });
  });

  it('a choice is the option\'s letter in the order the card lists them, the pattern the letter of the one that holds', () => {
    for (const question of QUESTIONS.filter((q) => q.kind === 'choice')) {
      const params = questionParams(question, SEED);
      const options = question.options(params);
      const right = options.findIndex((o) => o.id === trueOption(question, params).id);
      options.forEach((option, i) => {
        const record = scormInteraction({ position: 1, question, params, answer: option.id, at: AT });
        expect(record).toMatchObject({ type: 'choice', student_response: 'abc'[i], result: i === right ? 'correct' : 'wrong', 'correct_responses.0.pattern': 'abc'[right] });
      });
    }
    expect(interaction('metal-grazing', 'towards-white')).toMatchObject({ student_response: 'b', result: 'correct', 'correct_responses.0.pattern': 'b' });
  });

  it('ids tell a question asked twice on a sheet apart, and keep a question\'s id when it is checked again', () => {
    expect(interaction('exact-r', '0.1', 3).id).toBe('q03-exact-r');
    expect(interaction('exact-r', '0.2', 3).id).toBe('q03-exact-r');
    expect(interaction('exact-r', '0.1', 27).id).toBe('q27-exact-r');
    expect(interactionId(100, 'a b.c')).toBe('q100-a-b-c');
    expect(interactionId(1, 'x'.repeat(400))).toHaveLength(255);
  });

  it('writes CMIDecimal, CMITime and CMIString255 as SCORM 1.2 spells them', () => {
    expect([0, -0, 1e-7, 1.1 / 100, -3.25, 1e10, NaN, '1'].map((x) => cmiDecimal(x))).toEqual(['0', '0', '0.0000001', '0.011', '-3.25', null, null, null]);
    expect(cmiDecimal(-0.0001, 2)).toBe('0.00');
    expect(cmiTime(new Date(2026, 0, 1, 23, 59, 9))).toBe('23:59:09');
    expect(cmiTime(new Date(NaN))).toBeNull();
    expect(cmiString255('a\nb\u2028c\u0000d')).toBe('a b c d');
    expect(cmiString255('x'.repeat(254) + '😀')).toBe('x'.repeat(254)); // no half of the pair
    expect(cmiString255('\ud800x')).toBe('\ufffdx');
  });

  it('every answer the page can record gives an interaction valid in SCORM 1.2', () => {
    const answerFor = (question, params) => {
      if (question.kind === 'choice') return fc.constantFrom(...question.options(params).map((o) => o.id));
      if (question.kind === 'predict') return fc.integer({ min: 0, max: 900 }).map((t) => t / 10);
      return fc.oneof(anyText, fc.double().map(String), fc.double({ min: 0, max: 100 }).map((x) => `${x} %`))
        .map((t) => readAnswer(question, params, t)).filter((a) => a !== null);
    };
    const checked = fc.tuple(fc.constantFrom(...QUESTIONS), fc.string({ maxLength: 12 }), fc.integer({ min: 1, max: 40 }), fc.date({ noInvalidDate: true }))
      .chain(([question, seed, position, at]) => {
        const params = questionParams(question, seed);
        return answerFor(question, params).map((answer) => ({ question, params, position, answer, at }));
      });
    check(fc.property(checked, (input) => {
      const record = scormInteraction(input);
      expect(interactionProblems(record), JSON.stringify(record)).toEqual([]);
      expect(Object.keys(record)).toEqual(['id', 'type', 'student_response', 'result', 'time', 'correct_responses.0.pattern']);
      if (input.question.kind === 'numeric' && record.type === 'fill-in') expect(record.student_response).toBe(cmiString255(input.answer));
    }), 300);
    expect(MAX_TYPED).toBeLessThanOrEqual(255); // a typed answer always fits a fill-in response whole
  });
});

/** A window with a stand-in run-time: data it answers from, and every call it got. */
function lms(data = {}, { refuse = () => false } = {}) {
  const calls = [];
  const API = {
    LMSInitialize: () => 'true',
    LMSFinish: () => 'true',
    LMSCommit: () => { calls.push(['commit']); return 'true'; },
    LMSGetValue: (key) => data[key] ?? '',
    LMSSetValue: (key, value) => {
      if (refuse(key)) return 'false';
      calls.push([key, value]);
      data[key] = value;
      const n = /^cmi\.interactions\.(\d+)\.id$/.exec(key)?.[1];
      if (n !== undefined) data['cmi.interactions._count'] = String(Math.max(Number(data['cmi.interactions._count'] ?? 0), Number(n) + 1));
      return 'true';
    },
    LMSGetLastError: () => '0',
  };
  const win = { API, addEventListener: () => {} };
  win.parent = win;
  return { win, data, calls };
}

describe('the journal of interactions in the LMS', () => {
  const record = interaction('metal-grazing', 'towards-white');
  const written = (calls) => calls.filter(([key]) => key.startsWith('cmi.interactions.')).map(([key]) => key);

  it('appends each check at the next index, cmi.interactions._count, and commits it with the next save', () => {
    const { win, calls } = lms({ 'cmi.interactions._children': 'id,objectives,time,type,correct_responses,weighting,student_response,result,latency', 'cmi.interactions._count': '5' });
    const scorm = connectScorm(win);
    expect(scorm.record(record)).toBe(true);
    expect(scorm.record({ ...record, result: 'wrong' })).toBe(true);
    const elements = ['id', 'type', 'student_response', 'result', 'time', 'correct_responses.0.pattern'];
    expect(written(calls)).toEqual([5, 6].flatMap((n) => elements.map((e) => `cmi.interactions.${n}.${e}`)));
    calls.length = 0;
    expect(scorm.save({ seed: 's', answers: ['x'.repeat(5000)] })).toBe(false); // too long to keep,
    expect(calls).toEqual([['commit']]); // but what was recorded is committed
  });

  it('leaves out what _children does not list, and writes nothing where its list has no id', () => {
    const some = lms({ 'cmi.interactions._children': 'id,type,result', 'cmi.interactions._count': '0' });
    expect(connectScorm(some.win).record(record)).toBe(true);
    expect(written(some.calls)).toEqual(['cmi.interactions.0.id', 'cmi.interactions.0.type', 'cmi.interactions.0.result']);
    const none = lms({ 'cmi.interactions._children': 'objectives', 'cmi.interactions._count': '0' });
    expect(connectScorm(none.win).record(record)).toBe(false);
    expect(written(none.calls)).toEqual([]);
  });

  it('writes nothing without a count, and stops for the session once the LMS refuses an id', () => {
    const uncounted = lms({});
    expect(connectScorm(uncounted.win).record(record)).toBe(false);
    expect(written(uncounted.calls)).toEqual([]);
    const refusing = lms({ 'cmi.interactions._count': '0' }, { refuse: (key) => key.endsWith('.id') });
    const scorm = connectScorm(refusing.win);
    expect(scorm.record(record)).toBe(false);
    expect(scorm.record(record)).toBe(false);
    expect(written(refusing.calls)).toEqual([]);
  });

  it('survives an LMS that throws', () => {
    const { win } = lms({ 'cmi.interactions._count': '0' });
    win.API.LMSSetValue = () => { throw new Error('no'); };
    expect(connectScorm(win).record(record)).toBe(false);
  });
});
