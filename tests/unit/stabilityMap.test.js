import { describe, expect, it } from 'vitest';
import {
  ABOVE_TOLERANCE, classify, classifyValue, FINE, NOT_FINITE, OUT_OF_RANGE,
} from '../../src/methods/stabilityMap.js';
import { invisibleThreshold } from '../../src/methods/advisor.js';

const DEG = Math.PI / 180;

/** Failing cells as { ratio, theta } (degrees). */
function failures(map) {
  const out = [];
  for (let j = 0; j < map.height; j += 1) {
    for (let i = 0; i < map.width; i += 1) {
      if (map.cells[j * map.width + i] !== FINE) out.push({ ratio: map.ratio[j], theta: map.thetaDeg[i], cls: map.cells[j * map.width + i] });
    }
  }
  return out;
}

function rowNear(map, ratio) {
  let best = 0;
  map.ratio.forEach((r, j) => {
    if (Math.abs(r - ratio) < Math.abs(map.ratio[best] - ratio)) best = j;
  });
  return best;
}

describe('classifyValue', () => {
  it('NaN and Infinity first, then outside [0, 1], then error above tolerance', () => {
    expect(classifyValue(NaN, 0.5, 0.01)).toBe(NOT_FINITE);
    expect(classifyValue(-Infinity, 0.5, 0.01)).toBe(NOT_FINITE);
    expect(classifyValue(1.001, 1, 0.01)).toBe(OUT_OF_RANGE);
    expect(classifyValue(-0.001, 0, 0.01)).toBe(OUT_OF_RANGE);
    expect(classifyValue(0.52, 0.5, 0.01)).toBe(ABOVE_TOLERANCE);
    expect(classifyValue(0.505, 0.5, 0.01)).toBe(FINE);
    expect(classifyValue(1, 1, 0)).toBe(FINE);
  });
});

describe('stability map', () => {
  it('covers θ 0°–90° by nI/nT 0.4–2.5 with exactly 1 on the grid, tolerance = the 8-bit line', () => {
    const map = classify('exact-cg', 'fp64', { width: 19, height: 50 });
    expect(map.cells).toBeInstanceOf(Uint8Array);
    expect(map.cells).toHaveLength(19 * 50);
    expect(map.thetaDeg[0]).toBe(0);
    expect(map.thetaDeg[18]).toBe(90);
    expect(map.ratio[0]).toBe(0.4);
    expect(map.ratio[49]).toBe(2.5);
    expect([...map.ratio]).toContain(1);
    expect(map.tolerance).toBe(invisibleThreshold());
    expect(() => classify('conductor-exact', 'fp32')).toThrow(RangeError);
    expect(() => classify('exact-cg', 'fp32', { width: 1 })).toThrow(RangeError);
  });
  it('the safe exact form shows no failure in float64 or float32', () => {
    for (const precision of ['fp64', 'fp32']) {
      const map = classify('exact-cg', precision);
      expect(map.counts).toEqual({ fine: 181 * 106, aboveTolerance: 0, outOfRange: 0, notFinite: 0 });
    }
    expect(classify('exact-cg', 'fp64').maxError).toBeLessThan(1e-8);
  });
  it('the lecture order fails at matched media at grazing (float32: one cell, float16: a band)', () => {
    const fp32 = failures(classify('exact-cg-literal', 'fp32'));
    expect(fp32).toEqual([{ ratio: 1, theta: 90, cls: ABOVE_TOLERANCE }]);
    const fp16 = failures(classify('exact-cg-literal', 'fp16')).filter((f) => f.ratio === 1);
    expect(fp16.map((f) => f.theta)).toEqual([88.5, 89, 89.5, 90]);
  });
  it('Schlick without TIR fails on the glass side past the critical angle, by up to 0.96', () => {
    const map = classify('schlick-mul', 'fp32');
    const j = rowNear(map, 1.5);
    const critical = Math.asin(1 / map.ratio[j]) / DEG;
    for (let i = 0; i < map.width; i += 1) {
      const past = map.thetaDeg[i] > critical && map.thetaDeg[i] < 90; // at 90° both are 1
      if (past) expect(map.cells[j * map.width + i]).toBe(ABOVE_TOLERANCE);
    }
    expect(map.maxError).toBeGreaterThan(0.95);
    // the TIR-correct variant is fine past the critical angle on the same row
    const tir = classify('schlick-tir', 'fp32');
    for (let i = 0; i < tir.width; i += 1) {
      if (tir.thetaDeg[i] > critical + 0.5) expect(tir.cells[j * tir.width + i]).toBe(FINE);
    }
  });
  it('the exact forms in float16 fail near the critical angle and only there', () => {
    for (const id of ['exact-cg', 'exact-sp']) {
      const map = classify(id, 'fp16');
      const fails = failures(map);
      expect(fails.length).toBeGreaterThan(50);
      for (const f of fails) {
        expect(f.ratio).toBeGreaterThan(1);
        expect(Math.abs(f.theta - Math.asin(1 / f.ratio) / DEG)).toBeLessThan(3);
      }
      expect(map.maxError).toBeGreaterThan(0.15);
    }
  });
});
