import { describe, expect, it } from 'vitest';
import { HAND_IN_PREFIX, handInFromText, handInToCode, makeHandIn, sheetFromCode, sheetToCode } from '../../src/homework/sheetCodes.js';
import { gradeHandIn, readSheet } from '../../src/homework/readSheet.js';
import { readStartState } from '../../src/homework/readStartState.js';
import { angleOfMax, angleWhere } from '../../src/homework/solveAngle.js';
import { decimalsFor, formatValue } from '../../src/homework/page/formatAnswer.js';
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
    expect(readStartState('theta=10&fresnel=false&layer=both', 'exact-fresnel')).toEqual({ ok: true, state: { theta: 10, fresnel: false, layer: 'both' } });
    expect(readStartState('https://example.org/lab/embed.html?panel=asphalt&camEl=4&theme=light&lock=nT', 'asphalt')).toEqual({ ok: true, state: { camEl: 4 } });
    expect(readStartState('./index.html?asphalt.camEl=4&schlick.theta=3#asphalt', 'asphalt')).toEqual({ ok: true, state: { camEl: 4 } });
    expect(readStartState('', 'asphalt')).toEqual({ ok: true, state: {} });
    expect(readStartState('embed.html?panel=schlick&theta=1', 'asphalt')).toMatchObject({ ok: false });
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
