// `npm run bench -- --tiny` end to end on the site the browser tests already built (npm run
// test:e2e builds dist/ with the benchmark's three.js peer page): it serves it, runs the
// speed-accuracy benchmark and the pages' measurements (a class graded on the homework page among
// them) in headless Chromium (launched as playwright.config.js does) and writes results.json and
// results.png; here into a temporary folder, so bench/ keeps the committed run.
import { test, expect } from '@playwright/test';
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const METHOD_IDS = [
  'exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-pow', 'schlick-mul', 'schlick-tir', 'schlick-exp2',
  'conductor-exact', 'conductor-schlick', 'conductor-f82',
];

const isSpread = (s) => s && ['median', 'min', 'max'].every((k) => Number.isFinite(s[k])) && s.min <= s.median && s.median <= s.max;

test('npm run bench -- --tiny writes a valid results.json and a chart PNG', async () => {
  test.setTimeout(150_000); // the class graded on the homework page adds about 10 s
  const out = mkdtempSync(join(tmpdir(), 'fresnel-lab-bench-test-'));
  try {
    const { code, stdout, stderr } = await new Promise((done) => {
      execFile(process.execPath, ['bench/run.js', '--tiny', '--site', 'dist', '--out', out], { timeout: 140_000 }, (error, so, se) => {
        done({ code: error ? (error.code ?? 1) : 0, stdout: so, stderr: se });
      });
    });
    expect(code, stderr).toBe(0);
    for (const id of METHOD_IDS) expect(stdout).toContain(id);
    expect(stdout).toMatch(/Frames at 150×50 CSS px/);

    const results = JSON.parse(readFileSync(join(out, 'results.json'), 'utf8'));
    expect(typeof results.device.renderer).toBe('string');
    expect(results.device.timer).toMatch(/EXT_disjoint_timer_query_webgl2|wall clock/);
    expect(results.config.size).toBe('tiny');
    expect(results.methods.map((m) => m.id)).toEqual(METHOD_IDS);
    for (const m of results.methods) {
      expect(isSpread(m.gpu.nsPerEval), `${m.id} gpu`).toBe(true);
      expect(isSpread(m.gpu.mediump.nsPerEval), `${m.id} gpu mediump`).toBe(true);
      expect(isSpread(m.cpu.nsPerEval), `${m.id} cpu`).toBe(true);
      expect(m.cpu.where, `${m.id} cpu timed in a float64-only worker`).toBe('worker');
      for (const p of ['fp64', 'fp32', 'fp16']) {
        expect(Number.isFinite(m.error[p].max), `${m.id} ${p}`).toBe(true);
        expect(m.error[p].mean).toBeLessThanOrEqual(m.error[p].max);
      }
    }
    const exact = results.methods.find((m) => m.id === 'exact-cg').error;
    expect(exact.fp64.max).toBeLessThan(exact.fp32.max);
    // The errors read back from this GPU over the same default domains, beside the emulated ones.
    expect(results.device.gpuReadbackError).toBeNull();
    for (const m of results.methods) {
      for (const key of ['gpuHighp', 'gpuMediump']) {
        expect(Number.isFinite(m.error[key].max), `${m.id} ${key}`).toBe(true);
        expect(m.error[key].mean).toBeLessThanOrEqual(m.error[key].max);
      }
    }
    expect(Math.abs(exact.gpuHighp.max - exact.fp32.max)).toBeLessThan(1e-6); // float32 rounding level on any GPU
    expect(stdout).toMatch(/GPU highp\s+GPU mediump/);
    // The frame in its parts: the hero's three kinds of frame, the floor, and both peers.
    const f = results.frames;
    for (const key of ['spheres', 'spheresView', 'spheresOnePass', 'copy', 'threePhysical', 'threePlain']) {
      expect(isSpread(f[key].msPerFrame), key).toBe(true);
      expect(f[key].pixels, key).toBe(f.spheres.pixels);
    }
    expect(f.ratio).toBeCloseTo(f.spheres.msPerFrame.median / f.threePhysical.msPerFrame.median, 9);
    expect(f.plainRatio).toBeCloseTo(f.spheres.msPerFrame.median / f.threePlain.msPerFrame.median, 9);
    expect(stdout).toMatch(/hero, a change of the view\s+[\d.]+ \[/);
    expect(results.recommendations.plastic.invisible.methodId).toMatch(/^exact-/);
    // The normal-map viewer's chain build (64² when tiny), off the page's thread.
    const nm = results.normalMips;
    expect(nm.size).toBe(64);
    expect(nm.where).toMatch(/^\d workers?$/);
    expect(isSpread(nm.wallMs) && isSpread(nm.buildMs)).toBe(true);
    expect(nm.buildMs.median).toBeLessThanOrEqual(nm.wallMs.median);
    expect(Number.isFinite(nm.longestTaskMs) && Number.isFinite(nm.panelLongestTaskMs)).toBe(true);
    expect(nm.truth.samples).toBeGreaterThanOrEqual(128); // the default cap, reached
    expect(Number.isFinite(nm.truth.longestTaskMs)).toBe(true);
    expect(stdout).toMatch(/normal-mips: all six chains of a 64² map in \d+ ms/);

    // Grading a class on the homework page (50 hand-ins × 10 questions when tiny), from the zip and from pasted codes.
    const cv = results.pages.classView;
    expect([cv.students, cv.questions]).toEqual([50, 10]);
    for (const run of [cv, cv.codes]) {
      expect(isSpread(run.wallMs), `${run.source} wall`).toBe(true);
      expect(run.rows, run.source).toBe(cv.students); // a row per hand-in
      for (const key of ['longestTaskMs', 'longestScriptTaskMs', 'longestRenderMs', 'elementsPerStudent', 'elementsPerRow']) {
        expect(Number.isFinite(run[key]) && run[key] >= 0, `${run.source} ${key}`).toBe(true);
      }
      expect(run.longestTaskMs).toBe(Math.max(run.longestScriptTaskMs, run.longestRenderMs));
    }
    expect(cv.source).toBe('zip');
    expect(cv.codes.source).toBe('codes');
    expect(cv.elementsPerRow).toBeGreaterThan(cv.questions); // a cell per question at least
    expect(stdout).toMatch(/Grade a class, 50 hand-ins × 10 questions, from the zip to the whole gradebook/);

    const png = readFileSync(join(out, 'results.png'));
    expect(png.subarray(1, 4).toString()).toBe('PNG');
    expect(png.length).toBeGreaterThan(5000);
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
});
