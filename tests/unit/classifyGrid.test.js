import { describe, expect, it } from 'vitest';
import { cellAt, classifyGrid, columnCos, criticalAngleDeg, gridInputs } from '../../src/methods/classifyGrid.js';
import { classify, FINE, NOT_FINITE, OUT_OF_RANGE } from '../../src/methods/stabilityMap.js';
import { methodById } from '../../src/methods/methods.js';
import { fresnelExact } from '../../src/optics/fresnel.js';

/** The values classify() would compute, cell by cell, through gridInputs (as the GPU gets them). */
function valuesFromInputs(methodId, precision, map) {
  const inputs = gridInputs(map);
  const method = methodById(methodId);
  return Float64Array.from({ length: map.width * map.height }, (_, k) => method.evaluate(precision, inputs[k * 4], inputs[k * 4 + 1], inputs[k * 4 + 2]));
}

describe('gridInputs', () => {
  it('lays out (cos θ, ratio, 1, 0) per cell, row-major as classify(), cos 90° = 0', () => {
    const map = classify('exact-cg', 'fp64', { width: 19, height: 50 });
    const inputs = gridInputs(map);
    expect(inputs).toBeInstanceOf(Float32Array);
    expect(inputs).toHaveLength(19 * 50 * 4);
    expect([...inputs.slice(0, 4)]).toEqual([1, Math.fround(0.4), 1, 0]);
    expect(inputs[18 * 4]).toBe(0); // θ = 90° exactly grazing
    expect(inputs[(49 * 19 + 9) * 4 + 1]).toBe(2.5);
    expect(inputs[(49 * 19 + 9) * 4]).toBe(Math.fround(Math.cos(45 * Math.PI / 180)));
    expect(columnCos(90)).toBe(0);
    expect(columnCos(0)).toBe(1);
  });
});

describe('classifyGrid', () => {
  it('reproduces classify() exactly for float32 values fed through the GPU inputs', () => {
    for (const [id, precision] of [['exact-cg-literal', 'fp32'], ['schlick-mul', 'fp32'], ['exact-sp', 'fp16']]) {
      const map = classify(id, precision);
      const grid = classifyGrid(valuesFromInputs(id, precision, map), map, { methodId: id, precision });
      expect(grid.counts).toEqual(map.counts);
      expect(grid.cells).toEqual(map.cells);
      expect(grid.maxError).toBeCloseTo(map.maxError, 6);
      expect(grid.methodId).toBe(id);
      expect(grid.tolerance).toBe(map.tolerance);
    }
  });
  it('classifies NaN and Infinity as not finite and values outside [0, 1] as out of range', () => {
    const map = classify('exact-cg', 'fp64', { width: 3, height: 2 });
    const grid = classifyGrid([NaN, Infinity, -0.5, 1.5, 0.2, 1], { ...map, tolerance: 2 });
    expect([...grid.cells]).toEqual([NOT_FINITE, NOT_FINITE, OUT_OF_RANGE, OUT_OF_RANGE, FINE, FINE]);
    expect(grid.counts).toEqual({ fine: 2, aboveTolerance: 0, outOfRange: 2, notFinite: 2 });
    expect(() => classifyGrid([0], map)).toThrow(RangeError);
  });
  it('cellAt gives the coordinates and the float64 reference of a cell', () => {
    const map = classify('exact-cg', 'fp64');
    const cell = cellAt(map, 120, 55); // θ = 60°, ratio = 0.4 + 55·0.02 = 1.5
    expect(cell.thetaDeg).toBe(60);
    expect(cell.ratio).toBeCloseTo(1.5, 12);
    expect(cell.reference).toBe(fresnelExact(cell.cos, cell.ratio, 1));
    expect(cell.reference).toBe(1); // past the critical angle 41.8°
  });
  it('criticalAngleDeg: 41.81° for glass to air, none for ratio ≤ 1', () => {
    expect(criticalAngleDeg(1.5)).toBeCloseTo(41.8103, 4);
    expect(criticalAngleDeg(2.5)).toBeCloseTo(23.5782, 4);
    expect(criticalAngleDeg(1)).toBeNull();
    expect(criticalAngleDeg(0.5)).toBeNull();
  });
});
