import { describe, expect, it } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { resolveIncludes } from '../../src/gl/resolveIncludes.js';
import { maxError, niceCeil, reflectanceCurves, sampleAngles } from '../../src/optics/curves.js';
import { goldenMax } from '../../src/optics/refinedMax.js';
import { fresnelExact, fresnelSchlick } from '../../src/optics/fresnel.js';
import { dielectrics, dielectricById, metals, metalById, metalF0, dielectricSummary } from '../../src/optics/materials.js';
import { colormap, COLORMAP_STOPS } from '../../src/ui/colormap.js';
import { toCsv } from '../../src/host/exporters.js';
import { cappedPixelRatio } from '../../src/gl/cappedPixelRatio.js';

describe('GLSL includes', () => {
  const chunks = { a: 'float a;\n#include <b>', b: 'float b;', loop: '#include <loop>' };
  it('inlines chunks once, recursively', () => {
    const out = resolveIncludes('#include <a>\n#include <b>\nvoid main(){}', chunks);
    expect(out.match(/float b;/g)).toHaveLength(1);
    expect(out).toContain('float a;');
    expect(out).not.toMatch(/#include/);
  });
  it('reports missing chunks and cycles', () => {
    expect(() => resolveIncludes('#include <nope>', chunks)).toThrow(/nope/);
    expect(() => resolveIncludes('#include <loop>', chunks)).toThrow(/cycle/);
  });
  it('every shader in shaders/ resolves', () => {
    const files = Object.fromEntries(readdirSync('shaders').map((f) => [f.replace(/\.glsl$/, ''), readFileSync(`shaders/${f}`, 'utf8')]));
    for (const [name, text] of Object.entries(files)) expect(() => resolveIncludes(text, files), name).not.toThrow();
  });
  it('the GLSL twin defines every JS export of the optics core but the one docs/developer/architecture.md names', async () => {
    const glsl = readFileSync('shaders/fresnel.glsl', 'utf8');
    const jsOnly = ['conductorNormalIncidence']; // shaders take a metal's F0 from fresnelConductor at cos θ = 1
    const exported = Object.entries(await import('../../src/optics/fresnel.js')).filter(([, v]) => typeof v === 'function').map(([k]) => k);
    expect(exported).toEqual(expect.arrayContaining(jsOnly));
    for (const name of exported.filter((n) => !jsOnly.includes(n))) {
      expect(glsl, name).toMatch(new RegExp(`\\b(float|vec2|vec3) ${name}\\(`));
    }
    for (const name of jsOnly) expect(glsl).not.toMatch(new RegExp(`\\b${name}\\(`));
    expect(glsl).not.toMatch(/1\.0 \+ c \* c - m/); // the unsafe ordering
  });
});

describe('curves for the plot', () => {
  it('include the critical and Brewster angles as samples', () => {
    const t = sampleAngles(1.5, 1, 91);
    expect(t).toContain((Math.asin(1 / 1.5) * 180) / Math.PI);
    expect(t).toContain((Math.atan2(1, 1.5) * 180) / Math.PI);
    expect(t[0]).toBe(0);
    expect(t.at(-1)).toBe(90);
  });
  it('hold exact, Schlick, Rs, Rp and the error, and find the worst error', () => {
    const curves = reflectanceCurves(1, 1.5);
    expect(curves.exact[0]).toBeCloseTo(0.04, 15);
    expect(curves.exact.at(-1)).toBe(1);
    const worst = maxError(curves, 1, 1.5);
    expect(worst.value).toBeCloseTo(0.0357, 3);
    expect(worst.theta).toBeGreaterThan(84);
    expect(maxError(reflectanceCurves(1.5, 1), 1.5, 1).value).toBeGreaterThan(0.95); // Schlick misses TIR
  });
  it('refine the worst error off the grid, so both digits after the point hold', () => {
    // n_t = 1.75: the 0.25° grid's best sample is 85.50°; the maximum is at 85.4592° (a 1e-4° scan).
    const curves = reflectanceCurves(1, 1.75);
    let at = 0;
    curves.error.forEach((e, i) => { if (e > curves.error[at]) at = i; });
    expect(curves.theta[at]).toBe(85.5);
    const worst = maxError(curves, 1, 1.75);
    expect(worst.theta.toFixed(2)).toBe('85.46');
    const f = (t) => Math.abs(fresnelExact(Math.cos((t * Math.PI) / 180), 1, 1.75) - fresnelSchlick(Math.cos((t * Math.PI) / 180), 1, 1.75));
    for (let t = 84; t <= 87; t += 1e-3) expect(f(t)).toBeLessThanOrEqual(worst.value + 1e-16);
    // Glass to air: Schlick's worst is at the critical angle, a kink, which is found exactly.
    const tir = maxError(reflectanceCurves(1.5, 1), 1.5, 1);
    expect(tir.theta).toBeCloseTo((Math.asin(1 / 1.5) * 180) / Math.PI, 6);
    expect(goldenMax((t) => -((t - 0.3) ** 2), 0, 1)).toBeCloseTo(0.3, 9);
  });
  it('round a legend top up on the 1-2-5 ladder', () => {
    expect(niceCeil(0.0357)).toBeCloseTo(0.05, 15);
    expect(niceCeil(0.959)).toBe(1);
    expect(niceCeil(0.01)).toBeCloseTo(0.01, 15);
    expect(niceCeil(0.0101)).toBeCloseTo(0.02, 15);
    expect(niceCeil(0)).toBe(0.01);
  });
});

describe('materials', () => {
  it('holds the presets the hero offers, with sources', () => {
    for (const id of ['air', 'water', 'ice', 'glass', 'acrylic', 'pet', 'polycarbonate', 'diamond', 'skin', 'clear-coat']) {
      const m = dielectricById(id);
      expect(m, id).not.toBeNull();
      expect(m.n).toBeGreaterThanOrEqual(1);
      expect(m.n).toBeLessThan(2.5);
      expect(m.source.length).toBeGreaterThan(5);
    }
    expect(dielectrics.length).toBeGreaterThanOrEqual(10);
  });
  it('table values: water R0 0.0204 and critical angle 48.6°', () => {
    const water = dielectricSummary(dielectricById('water'));
    expect(water.r0).toBeCloseTo(0.0204, 4);
    expect((water.criticalAngle * 180) / Math.PI).toBeCloseTo(48.6, 1);
    expect(water.speed).toBeCloseTo(0.75, 2);
  });
  it('metals: gold F0 is about (0.96, 0.79, 0.41) from n + ik', () => {
    expect(metals.map((m) => m.id)).toEqual(['gold', 'silver', 'copper', 'aluminium', 'iron']);
    const f0 = metalF0(metalById('gold'));
    [0.957, 0.792, 0.408].forEach((v, i) => expect(f0[i]).toBeCloseTo(v, 2)); // the reference table's rounding
  });
});

describe('small helpers', () => {
  it('the colormap hits its stops and clamps', () => {
    expect(colormap(0)).toEqual(COLORMAP_STOPS[0]);
    expect(colormap(1)).toEqual(COLORMAP_STOPS[4]);
    expect(colormap(0.5)).toEqual(COLORMAP_STOPS[2]);
    expect(colormap(-3)).toEqual(COLORMAP_STOPS[0]);
    expect(colormap(0.125)[0]).toBeCloseTo((COLORMAP_STOPS[0][0] + COLORMAP_STOPS[1][0]) / 2, 12);
  });
  it('CSV has a header and full-precision numbers', () => {
    expect(toCsv({ a: [1, 0.1 + 0.2], b: [2, 3] })).toBe('a,b\n1,2\n0.30000000000000004,3\n');
  });
  it('pixel ratio is capped for large screens', () => {
    expect(cappedPixelRatio(800, 300, 2)).toBe(2);
    expect(cappedPixelRatio(800, 300, 3)).toBe(2);
    const r = cappedPixelRatio(3840, 1400, 2);
    expect(3840 * 1400 * r * r).toBeLessThanOrEqual(3_000_001);
  });
});
