import { describe, expect, it } from 'vitest';
import { HALF_STEP_CODES, methodError } from '../../src/methods/advisor.js';
import {
  criterionText, DEFAULT_BUDGET, DISPLAY_BUDGETS, displayBudget, meanDisplayCodes, recommendWithin,
} from '../../src/methods/displayBudgets.js';
import { methodById } from '../../src/methods/methods.js';
import { paretoFront } from '../../src/methods/paretoFront.js';
import { sceneById } from '../../src/methods/scenes.js';

const SCHLICK = ['schlick-pow', 'schlick-mul', 'schlick-exp2', 'schlick-tir'];
const TIR_AWARE = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-tir'];
const row = (result, id) => result.table.find((r) => r.methodId === id);

describe('paretoFront', () => {
  it('keeps exactly the points nothing beats on both axes, cheapest first', () => {
    const points = [
      { x: 4, y: 12 }, // cheapest: on the front
      { x: 6, y: 12 }, // as accurate, dearer: dominated
      { x: 5, y: 12.5 }, // dearer and worse than the first: dominated
      { x: 16, y: 1e-4 }, // far more accurate: on the front
      { x: 14, y: 10 }, // between: on the front
      { x: 18, y: 2e-5 }, // most accurate: on the front
      { x: 17, y: 1e-4 }, // ties the error of a cheaper one: dominated
    ];
    expect(paretoFront(points)).toEqual([0, 4, 3, 5]);
  });
  it('drops NaN errors and costs, keeps the first of exact duplicates, handles empty input', () => {
    expect(paretoFront([{ x: 1, y: NaN }, { x: 2, y: 3 }, { x: NaN, y: 0 }, { x: 3, y: Infinity }])).toEqual([1]);
    expect(paretoFront([{ x: 2, y: 1 }, { x: 2, y: 1 }])).toEqual([0]);
    expect(paretoFront([{ x: 2, y: 5 }, { x: 2, y: 1 }])).toEqual([1]); // same cost: the more accurate
    expect(paretoFront([])).toEqual([]);
    // Negative measured costs (timer noise) are still ordered correctly.
    expect(paretoFront([{ x: -1, y: 10 }, { x: 0.5, y: 1 }, { x: 0.2, y: 20 }])).toEqual([0, 1]);
  });
});

describe('display budgets', () => {
  it('start at the issue\'s invisible line and grow; acceptable is 5 % of the 8-bit range', () => {
    expect(DEFAULT_BUDGET).toBe('invisible');
    expect(displayBudget('invisible').codes).toBe(HALF_STEP_CODES);
    expect(displayBudget('acceptable').codes).toBe(0.05 * 255);
    expect(displayBudget('one-percent').codes).toBeCloseTo(0.01 * 255, 12);
    const codes = DISPLAY_BUDGETS.map((b) => b.codes);
    expect(codes).toEqual([...codes].sort((a, b) => a - b));
    expect(() => displayBudget('whatever')).toThrow(RangeError);
    expect(criterionText()).toMatch(/worst pixel/);
  });

  it('invisible: no Schlick variant passes for plastic, not even on the average pixel', () => {
    const r = recommendWithin(sceneById('plastic'), {}, 'invisible');
    expect(r.methodId).toBe('exact-cg');
    expect(r.budget.id).toBe('invisible');
    for (const id of SCHLICK) {
      expect(row(r, id).passes).toBe(false);
      // The cosine-weighted average display error is still several codes: sRGB steepens the
      // small errors of dark reflections, so a realistic weighting does not rescue Schlick here.
      const mean = meanDisplayCodes(sceneById('plastic'), methodById(id));
      expect(mean).toBeGreaterThan(3);
      expect(mean).toBeLessThan(row(r, id).maxCodes);
    }
    expect(meanDisplayCodes(sceneById('plastic'), methodById('schlick-mul'))).toBeCloseTo(4.03, 2);
  });

  it('acceptable (5 %): Schlick for opaque plastic, a TIR-aware method for glass from inside', () => {
    const plastic = recommendWithin(sceneById('plastic'), {}, 'acceptable');
    expect(SCHLICK).toContain(plastic.methodId);
    expect(plastic.methodId).toBe('schlick-pow'); // the lowest static count
    expect(row(plastic, 'schlick-mul').maxCodes).toBeLessThan(12.75); // 12.07: passes, but only just
    expect(row(plastic, 'schlick-mul').maxCodes).toBeGreaterThan(0.9 * 12.75); // "just above" Schlick's worst, the panel says
    expect(row(plastic, 'schlick-mul').maxCodes).toBeGreaterThan(12);
    const glass = recommendWithin(sceneById('glass-inside'), {}, 'acceptable');
    expect(TIR_AWARE).toContain(glass.methodId);
    expect(glass.methodId).toBe('schlick-tir');
    for (const id of ['schlick-pow', 'schlick-mul', 'schlick-exp2']) expect(row(glass, id).passes).toBe(false);
    expect(recommendWithin(sceneById('glass-inside'), {}, 'invisible').methodId).toBe('exact-cg');
  });

  it('acceptable agrees with what engines ship (Schlick) on every other scene', () => {
    expect(recommendWithin(sceneById('ice-water'), {}, 'acceptable').methodId).toBe('exact-cg'); // Schlick 115 codes off
    const metal = recommendWithin(sceneById('metal'), {}, 'acceptable');
    expect(metal.methodId).toBe('conductor-f82'); // Schlick on aluminium: 15.5 codes
    expect(row(metal, 'conductor-schlick').passes).toBe(false);
    expect(SCHLICK).toContain(recommendWithin(sceneById('phone-mediump'), {}, 'acceptable').methodId);
    expect(recommendWithin(sceneById('phone-mediump'), {}, 'acceptable').precision).toBe('fp16');
  });

  it('measured costs pick the cheapest passing method, whatever the static counts say', () => {
    const measured = { 'schlick-pow': 11.6, 'schlick-mul': 1.8, 'schlick-exp2': 8.4, 'schlick-tir': 5.4, 'exact-cg': 6.1, 'exact-cg-literal': 6.5, 'exact-sp': 5.4 };
    const r = recommendWithin(sceneById('plastic'), measured, 'acceptable');
    expect(r.methodId).toBe('schlick-mul');
    expect(row(r, 'schlick-mul').costSource).toBe('measured');
    expect(recommendWithin(sceneById('plastic'), measured, 'invisible').methodId).toBe('exact-sp');
  });

  it('the average display error is cached and agrees with the worst one for exact methods', () => {
    const scene = sceneById('glass-inside');
    const a = meanDisplayCodes(scene, methodById('exact-cg'));
    expect(meanDisplayCodes(scene, methodById('exact-cg'))).toBe(a);
    expect(a).toBeLessThanOrEqual(methodError(scene, methodById('exact-cg')).maxCodes);
    expect(a).toBeLessThan(1e-3);
  });
});
