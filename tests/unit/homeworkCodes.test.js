import { describe, expect, it } from 'vitest';
import { HAND_IN_PREFIX, handInFromText, handInToCode, makeHandIn, sheetFromCode, sheetToCode } from '../../src/homework/sheetCodes.js';
import { readSheet } from '../../src/homework/readSheet.js';
import { gradeHandIn } from '../../src/homework/gradeHandIn.js';
import { readStartState } from '../../src/homework/readStartState.js';
import { angleOfMax, angleWhere } from '../../src/optics/solveAngle.js';
import { decimalsFor, formatValue } from '../../src/homework/formatAnswer.js';
import { questionById } from '../../src/homework/questions.js';

const sheet = { version: 1, title: 'Brechung – élève ✓', items: [{ question: 'exact-r', state: { theta: 10 } }, { question: 'metal-grazing' }] };

describe('sheet and hand-in codes', () => {
  it('round-trip any text, in characters a link keeps', () => {
    const code = sheetToCode(sheet);
    expect(code).toMatch(/^[A-Za-z0-9_-]+$/);
    expect(sheetFromCode(code)).toEqual({ ok: true, data: sheet });
    const handIn = makeHandIn({ sheet, seed: 'ab12cd34', name: 'Zoë', answers: ['0.5', 'towards-white'], time: '2026-12-02T10:00:00.000Z' });
    const text = handInToCode(handIn);
    expect(text.startsWith(HAND_IN_PREFIX)).toBe(true);
    expect(handInFromText(`  ${text}\n`)).toEqual({ ok: true, data: handIn });
    expect(handInFromText(JSON.stringify(handIn))).toEqual({ ok: true, data: handIn });
  });
  it('refuse damaged, cut or foreign text with a reason', () => {
    const code = sheetToCode(sheet);
    for (const bad of ['', 'abc$%', code.slice(0, code.length - 7), 'x'.repeat(200_001)]) {
      const read = sheetFromCode(bad);
      expect(read.ok, bad.slice(0, 20)).toBe(false);
      expect(read.problems[0]).toMatch(/sheet link/);
    }
    for (const bad of ['', 'hello', '{"a":', `${HAND_IN_PREFIX}!!`]) expect(handInFromText(bad).ok, bad).toBe(false);
  });
});

describe('sheets with start states, hand-ins with names and times', () => {
  it('keep an item\'s start state and a class seed; refuse bad ones', () => {
    expect(readSheet({ ...sheet, seed: 'class' })).toMatchObject({ ok: true, sheet: { seed: 'class', items: [{ question: 'exact-r', state: { theta: 10 } }, { question: 'metal-grazing' }] } });
    for (const state of [[], 'theta=10', { 'bad key': 1 }, { theta: Infinity }, { theta: { deep: 1 } }, Object.fromEntries(Array.from({ length: 25 }, (_, i) => [`k${i}`, 1]))]) {
      expect(readSheet({ ...sheet, items: [{ question: 'exact-r', state }] }).ok, JSON.stringify(state)).toBe(false);
    }
    expect(readSheet({ ...sheet, seed: '' }).ok).toBe(false);
  });
  it('a hand-in reports its name and time, and must say its version', () => {
    const handIn = makeHandIn({ sheet, seed: 's', name: 'Ada', answers: [null, null], time: '2026-12-02T10:00:00.000Z' });
    expect(gradeHandIn(handIn)).toMatchObject({ ok: true, name: 'Ada', time: '2026-12-02T10:00:00.000Z', score: 0, total: 2 });
    expect(gradeHandIn({ ...handIn, name: 7, time: 'yesterday' })).toMatchObject({ ok: true, name: '', time: null });
    expect(gradeHandIn({ ...handIn, version: 2 }).ok).toBe(false);
  });
});

describe('start states from links', () => {
  it('reads pairs, embed links and lecture links, typed', () => {
    expect(readStartState('camEl=10&fresnel=false&roughness=0.5', 'asphalt')).toEqual({ ok: true, state: { camEl: 10, fresnel: false, roughness: 0.5 } });
    expect(readStartState('https://example.org/lab/embed.html?panel=asphalt&camEl=4&theme=light&lock=nT', 'asphalt')).toEqual({ ok: true, state: { camEl: 4 } });
    expect(readStartState('./index.html?asphalt.camEl=4&schlick.theta=3#asphalt', 'asphalt')).toEqual({ ok: true, state: { camEl: 4 } });
    expect(readStartState('', 'asphalt')).toEqual({ ok: true, state: {} });
    expect(readStartState('embed.html?panel=schlick&theta=1', 'asphalt')).toEqual({ ok: false, problem: 'This link is for “Schlick\'s approximation”, not “Does asphalt have a specular highlight?”.' });
  });
});

describe('angles found numerically', () => {
  it('bisection finds a crossing and the refined maximum beats the grid', () => {
    expect(angleWhere((t) => t * t, 2, 0, 90)).toBeCloseTo(Math.SQRT2, 10);
    expect(() => angleWhere((t) => t, 100)).toThrow(RangeError);
    const f = (t) => -((t - 33.333333) ** 2);
    expect(angleOfMax(f)).toBeCloseTo(33.333333, 6);
  });
});

describe('printed answers', () => {
  it('show the decimals asked for and one more', () => {
    expect(decimalsFor(questionById('exact-r'))).toBe(4); // "to 3 decimals", ±0.0005
    expect(decimalsFor(questionById('r0-value'))).toBe(5); // "to 4 decimals"
    expect(decimalsFor(questionById('brewster-exact'))).toBe(2); // "to 0.1°"
    expect(formatValue(questionById('brewster-predict'), 56.30993247)).toBe('56.31°');
  });
});

describe('answers read back for their kind', () => {
  it('a prediction is an angle, a choice one of its options, a typed answer a short text', async () => {
    const { readAnswer } = await import('../../src/homework/gradeAnswer.js');
    const predict = questionById('brewster-predict');
    const choice = questionById('metal-grazing');
    const numeric = questionById('exact-r');
    const p = { metal: 'gold' };
    expect(readAnswer(predict, {}, 56.3)).toBe(56.3);
    for (const bad of ['56', -1, 91, NaN, null, {}]) expect(readAnswer(predict, {}, bad)).toBeNull();
    expect(readAnswer(choice, p, 'towards-white')).toBe('towards-white');
    for (const bad of ['nope', 1, null]) expect(readAnswer(choice, p, bad)).toBeNull();
    expect(readAnswer(numeric, {}, '0.5')).toBe('0.5');
    expect(readAnswer(numeric, {}, 'x'.repeat(200))).toHaveLength(80);
    for (const bad of ['', '  ', 0.5, null]) expect(readAnswer(numeric, {}, bad)).toBeNull();
  });
});

describe('hand-ins against the sheet that was set', () => {
  const set = readSheet(sheet).sheet;
  const handIn = (over = {}) => makeHandIn({ sheet, seed: 's1', answers: [null, null], ...over });
  it('a hand-in for an edited or another sheet is refused when the set sheet is given', () => {
    expect(gradeHandIn(handIn(), { expected: set })).toMatchObject({ ok: true, total: 2 });
    const edited = { ...sheet, items: [sheet.items[1]] };
    const refused = gradeHandIn(handIn({ sheet: edited, answers: [null] }), { expected: set });
    expect(refused.ok).toBe(false);
    expect(refused.problems[0]).toMatch(/another sheet \(fingerprint \w+\)/);
    // Without the set sheet it is graded as what it says it is, and its fingerprint tells.
    expect(gradeHandIn(handIn({ sheet: edited, answers: [null] })).fingerprint).not.toBe(gradeHandIn(handIn()).fingerprint);
  });
  it('a class seed is the only seed its sheet is graded with', () => {
    const classSheet = { ...sheet, seed: 'class' };
    expect(gradeHandIn(handIn({ sheet: classSheet, seed: 'class' })).ok).toBe(true);
    expect(gradeHandIn(handIn({ sheet: classSheet, seed: 'mine' }))).toMatchObject({ ok: false, problems: [expect.stringMatching(/seed class/)] });
  });
  it('answers of the wrong kind count as none; tries are reported, not graded', () => {
    const graded = gradeHandIn(handIn({ answers: [0.5, 7], attempts: [3, 'x'] }));
    expect(graded.results.map((r) => [r.answered, r.attempts])).toEqual([[false, 3], [false, null]]);
  });
  it('a start state may not set the embed page\'s own options', () => {
    for (const key of ['panel', 'lock', 'parentOrigin', 'controls']) {
      const read = readSheet({ ...sheet, items: [{ question: 'exact-r', state: { [key]: 'x' } }] });
      expect(read.ok, key).toBe(false);
      expect(read.problems[0]).toContain('option of the embed page');
    }
  });
  it('codes wrapped by a mail program or padded still read', () => {
    const code = handInToCode(handIn());
    const wrapped = code.replace(/(.{60})/g, '$1\n  ');
    expect(handInFromText(wrapped)).toEqual(handInFromText(code));
    expect(sheetFromCode(`${sheetToCode(sheet)}==`)).toEqual(sheetFromCode(sheetToCode(sheet)));
  });
});
