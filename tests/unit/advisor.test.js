import { describe, expect, it } from 'vitest';
import {
  displayCodes, HALF_STEP_CODES, invisibleThreshold, methodError, recommend, srgbDecode, srgbEncode,
} from '../../src/methods/advisor.js';
import { methodById } from '../../src/methods/methods.js';
import { SCENES, sceneById } from '../../src/methods/scenes.js';

const DEG = Math.PI / 180;
const SCHLICK = ['schlick-pow', 'schlick-mul', 'schlick-exp2', 'schlick-tir'];
const TIR_AWARE = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-tir'];
const row = (result, id) => result.table.find((r) => r.methodId === id);

describe('the 8-bit visibility line', () => {
  it('sRGB encode and decode are inverse and hit the standard breakpoints', () => {
    for (const x of [0, 0.001, 0.0031308, 0.04, 0.2, 0.5, 1]) expect(srgbDecode(srgbEncode(x))).toBeCloseTo(x, 12);
    expect(srgbEncode(1)).toBeCloseTo(1, 12);
    expect(srgbEncode(0.18)).toBeCloseTo(0.4614, 4); // 18% grey is code 118
  });
  it('half a step is 0.0044548 in linear at white and 1.5176e-4 at black', () => {
    expect(invisibleThreshold()).toBeCloseTo(0.0044548, 7);
    expect(invisibleThreshold(1)).toBe(invisibleThreshold());
    expect(invisibleThreshold(0)).toBeCloseTo(0.5 / 255 / 12.92, 12);
    expect(invisibleThreshold(0.04)).toBeGreaterThan(invisibleThreshold(0));
    expect(invisibleThreshold(0.04)).toBeLessThan(invisibleThreshold(1));
    expect(displayCodes(1 - invisibleThreshold(), 1)).toBeCloseTo(HALF_STEP_CODES, 9);
  });
  it('display error clamps like a framebuffer and makes NaN infinitely visible', () => {
    expect(displayCodes(1.2, 1)).toBe(0);
    expect(displayCodes(NaN, 0.5)).toBe(Infinity);
    expect(displayCodes(0, 1)).toBeCloseTo(255, 9);
  });
});

describe('recommend', () => {
  it('opaque plastic: every Schlick variant is 12 codes off, so the invisible choice is exact c/g', () => {
    const r = recommend(sceneById('plastic'));
    expect(r.methodId).toBe('exact-cg');
    expect(r.invisible).toBe(true);
    expect(r.precision).toBe('fp32');
    expect(row(r, 'schlick-mul').max).toBeCloseTo(0.0683, 4); // n = 1.3 at 83.6° (the same sweep gives 0.0599 at n = 1.33)
    expect(row(r, 'schlick-mul').maxCodes).toBeCloseTo(12.07, 1);
    expect(row(r, 'schlick-mul').thetaAtMax / DEG).toBeCloseTo(83.6, 0);
    expect(row(r, 'schlick-mul').caseAtMax).toEqual([1, 1.3]);
    expect(row(r, 'exact-cg').max).toBeLessThan(1e-6);
    expect(r.reason).toMatch(/^Exact c\/g \(safe order\) .* cheapest/);
    expect(r.reason).toMatch(/Schlick, multiplications only/);
    expect(r.table.map((x) => x.cost)).toEqual([...r.table.map((x) => x.cost)].sort((a, b) => a - b));
  });
  it('with a budget of 13 codes (engines ship Schlick for plastic), a Schlick variant wins', () => {
    const r = recommend(sceneById('plastic'), {}, { budgetCodes: 13 });
    expect(SCHLICK).toContain(r.methodId);
    expect(r.methodId).toBe('schlick-pow'); // the smallest static count; pow is 2 SFU ops in practice
    const measured = { 'schlick-pow': 9, 'schlick-mul': 5, 'schlick-exp2': 6, 'schlick-tir': 11, 'exact-cg': 14, 'exact-cg-literal': 15, 'exact-sp': 16 };
    const m = recommend(sceneById('plastic'), measured, { budgetCodes: 13 });
    expect(m.methodId).toBe('schlick-mul');
    expect(row(m, 'schlick-mul').costSource).toBe('measured');
  });
  it('glass or water seen from inside: a TIR-aware method; Schlick on cos θi is off by 0.975', () => {
    const r = recommend(sceneById('glass-inside'));
    expect(TIR_AWARE).toContain(r.methodId);
    expect(r.methodId).toBe('exact-cg');
    expect(row(r, 'schlick-mul').max).toBeCloseTo(0.975, 3); // water → air at 48.75°
    expect(row(r, 'schlick-tir').maxCodes).toBeCloseTo(10.3, 1);
    const relaxed = recommend(sceneById('glass-inside'), {}, { budgetCodes: 13 });
    expect(relaxed.methodId).toBe('schlick-tir');
    for (const id of ['schlick-pow', 'schlick-mul', 'schlick-exp2']) expect(row(relaxed, id).passes).toBe(false);
  });
  it('measured costs reorder the choice', () => {
    const r = recommend(sceneById('glass-inside'), { 'exact-sp': 1, 'exact-cg': 2, 'exact-cg-literal': 2, 'schlick-tir': 3, 'schlick-pow': 4, 'schlick-mul': 4, 'schlick-exp2': 4 });
    expect(r.methodId).toBe('exact-sp');
  });
  it('ice in water picks the safe exact form, never the lecture order', () => {
    const r = recommend(sceneById('ice-water'));
    expect(r.methodId).toBe('exact-cg');
    expect(row(r, 'schlick-tir').max).toBeCloseTo(0.474, 3); // Cycles: Schlick fails near IOR 1
  });
  it('a metal: exact conductor; F82-tint at a few codes beats Schlick on aluminium', () => {
    const r = recommend(sceneById('metal'));
    expect(r.methodId).toBe('conductor-exact');
    expect(row(r, 'conductor-schlick').max).toBeCloseTo(0.130, 3); // aluminium 650 nm (Rakić 1995 n, k), against the exact conductor formula
    expect(row(r, 'conductor-f82').max).toBeCloseTo(0.0219, 3);
    expect(recommend(sceneById('metal'), {}, { budgetCodes: 10 }).methodId).toBe('conductor-f82');
  });
  it('phone mediump: float16 exact c/g is still invisible for plastic (0.34 codes)', () => {
    const r = recommend(sceneById('phone-mediump'));
    expect(r.precision).toBe('fp16');
    expect(r.methodId).toBe('exact-cg');
    expect(row(r, 'exact-cg').max).toBeGreaterThan(1e-3); // float16 rounding, not the formula
    expect(row(r, 'exact-cg').maxCodes).toBeLessThan(0.5);
  });
  it('glass from inside in float16: nothing is invisible, the most accurate is chosen and said so', () => {
    const r = recommend(sceneById('glass-inside'), {}, { precision: 'fp16' });
    expect(r.invisible).toBe(false);
    expect(r.reason).toMatch(/^No method/);
    const best = Math.min(...r.table.map((x) => x.maxCodes));
    expect(row(r, r.methodId).maxCodes).toBe(best);
    expect(row(r, 'exact-cg').max).toBeGreaterThan(0.1); // near the critical angle
  });
  it('every scene has a domain, a precision and a weighting', () => {
    expect(SCENES.map((s) => s.id)).toEqual(['plastic', 'glass-inside', 'ice-water', 'metal', 'phone-mediump']);
    for (const s of SCENES) {
      expect(['fp32', 'fp16']).toContain(s.precision);
      expect(['uniform', 'cosine']).toContain(s.weighting);
      expect(s.cases.length).toBeGreaterThan(0);
    }
    expect(sceneById('metal').cases).toHaveLength(6);
    expect(() => sceneById('moon')).toThrow(RangeError);
    expect(methodError(sceneById('ice-water'), methodById('exact-cg'))).toBe(methodError(sceneById('ice-water'), methodById('exact-cg')));
  });
});

describe('methods kept only to show a failure', () => {
  it('the lecture-order exact form is never recommended, even when measured cheapest and invisible', () => {
    const scene = sceneById('plastic');
    const costs = { 'exact-cg-literal': 1, 'exact-cg': 5, 'exact-sp': 6, 'schlick-mul': 2, 'schlick-pow': 3, 'schlick-tir': 4, 'schlick-exp2': 3 };
    const result = recommend(scene, costs);
    const literal = result.table.find((row) => row.methodId === 'exact-cg-literal');
    expect(literal.passes).toBe(true); // it is invisible for plastic in float32...
    expect(result.methodId).toBe('exact-cg'); // ...but the safe order is what gets recommended
    expect(result.reason).toContain('not recommended');
  });
});
