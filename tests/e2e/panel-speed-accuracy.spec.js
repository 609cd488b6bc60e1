import { test, expect, animationFrames, openLab } from './fixtures.js';
import { thetaSamples } from '../../src/methods/errorMetrics.js';
import { fresnelExact } from '../../src/optics/fresnel.js';

const PANEL = 'speed-accuracy';
const SCHLICK = ['schlick-pow', 'schlick-mul', 'schlick-exp2', 'schlick-tir'];
const TIR_AWARE = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-tir'];
const DIELECTRICS = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-pow', 'schlick-mul', 'schlick-tir', 'schlick-exp2'];
const CONDUCTORS = ['conductor-exact', 'conductor-schlick', 'conductor-f82'];

const view = (page) => page.evaluate((id) => {
  const { rows, mode, rec } = window.fresnelLab.panels[id].view;
  return { mode, methodId: rec.methodId, rows: rows.map((r) => ({ id: r.methodId, x: r.x, y: r.maxCodes, max: r.max, passes: r.passes })) };
}, PANEL);

async function choose(page, label, option) {
  await page.locator('.lil-controller', { hasText: label }).locator('select').selectOption({ label: option });
}

/** The option the "Error measured by" control shows. */
const sourceOption = (page) => page.locator('.lil-controller', { hasText: 'Error measured by' }).locator('select option:checked');

const gpuMeasured = (page) => page.evaluate((id) => window.fresnelLab.panels[id].gpuMeasurement, PANEL);

// sRGB encoding (IEC 61966-2-1) of a value clamped to [0, 1], in 8-bit codes: the test's own
// oracle for the display error the chart plots (the panel's is advisor.displayCodes).
const codes = (x) => {
  const v = Math.min(1, Math.max(0, x));
  return 255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * v ** (1 / 2.4) - 0.055);
};

/**
 * Max |ΔR| and worst display codes of dielectric methods over a scene's domain ({ cases,
 * thetaCount, weighting }), from values evaluated on this GPU by another panel's evaluator (the
 * stability panel's evaluateMethodsGpu handle), with the float64 reference computed here: an
 * independent check of the panel's read-back path.
 */
async function gpuErrors(browserPage, scene, methodIds, precision) {
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  const samples = scene.cases.flatMap(([nI, nT]) => Array.from(cos, (c) => [c, nI, nT]));
  const page = await browserPage.context().newPage();
  await openLab(page, './embed.html?panel=stability');
  const values = await page.evaluate(({ ids, rows, p }) => {
    const { gpu } = window.fresnelLab.panels.stability;
    const inputs = new Float32Array(rows.flatMap(([c, nI, nT]) => [c, nI, nT, 0]));
    return ids.map((methodId) => Array.from(gpu.evaluate({ methodId, precision: p, inputs })));
  }, { ids: methodIds, rows: samples, p: precision });
  await page.close();
  return Object.fromEntries(methodIds.map((methodId, m) => {
    let max = 0;
    let maxCodes = 0;
    samples.forEach(([c, nI, nT], i) => {
      const ref = fresnelExact(c, nI, nT);
      max = Math.max(max, Math.abs(values[m][i] - ref));
      maxCodes = Math.max(maxCodes, Math.abs(codes(values[m][i]) - codes(ref)));
    });
    return [methodId, { max, maxCodes }];
  }));
}

test('renders every method as a point and a table row, with no console errors', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  const chart = page.locator('.sa-chart');
  await expect(chart).toBeVisible();
  await expect(chart).toHaveAttribute('aria-label', /Pareto front/);
  const plastic = await view(page);
  expect(plastic.rows.map((r) => r.id).sort()).toEqual([...DIELECTRICS].sort());
  expect(plastic.mode).toBe('static'); // no run yet: the static counts
  await expect(page.locator('.sa-table tbody tr')).toHaveCount(7);
  for (const r of plastic.rows) expect(Number.isFinite(r.x) && r.y >= 0).toBe(true);
  await choose(page, 'Scene', 'A metal (gold, aluminium)');
  await expect(page.locator('.sa-table tbody tr')).toHaveCount(3);
  expect((await view(page)).rows.map((r) => r.id).sort()).toEqual([...CONDUCTORS].sort());
  // The chart is drawn: some pixels differ from the background.
  const busy = await page.evaluate(() => {
    const c = document.querySelector('.sa-chart');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let differ = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] !== d[0] || d[i + 1] !== d[1] || d[i + 2] !== d[2]) differ += 1;
    return differ / (d.length / 4);
  });
  expect(busy).toBeGreaterThan(0.02);
  await expect(page.locator('.panel-description')).toContainText('recommendation is');
});

test('the scene and the budget change the recommendation, as the advisor reasons', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  // Invisible (½ step, the default): Schlick is 12 codes off on plastic, so exact c/g.
  await expect(page.locator('.sa-pick-method')).toHaveText('Exact c/g (safe order)');
  await expect(page.locator('.sa-criterion')).toContainText('worst pixel');
  expect((await view(page)).rows.find((r) => r.id === 'schlick-mul').y).toBeCloseTo(12.07, 1);
  // The reason also names what the lenient budget would pick, with its measured error.
  await expect(page.locator('.sa-reason'))
    .toContainText(/If an error of up to 5 % of the display range .* Schlick, pow\(1 − c, 5\) would do: 12\.1 codes at worst, /);
  // The documented "acceptable" budget (5 % of the range): a Schlick variant for opaque plastic...
  await choose(page, 'Error budget', 'Acceptable: 5 % of the range (12.75 codes)');
  await expect(page.locator('.sa-pick-method')).toContainText('Schlick');
  expect(SCHLICK).toContain((await view(page)).methodId);
  await expect(page.locator('.sa-reason')).not.toContainText('If an error of up to 5 %'); // already the lenient budget
  const before = await page.locator('.sa-chart').screenshot();
  // ...and a TIR-aware one for glass seen from inside, where plain Schlick is 0.975 off.
  await choose(page, 'Scene', 'Glass or water seen from inside');
  await expect(page.locator('.sa-pick-method')).toHaveText('Schlick on cos θt (TIR-correct)');
  const glass = await view(page);
  expect(TIR_AWARE).toContain(glass.methodId);
  expect(glass.rows.find((r) => r.id === 'schlick-mul').passes).toBe(false);
  expect(Buffer.compare(before, await page.locator('.sa-chart').screenshot())).not.toBe(0);
  await expect(page).toHaveURL(/scene=glass-inside/);
  await expect(page).toHaveURL(/budget=acceptable/);
});

test('URL parameters choose the scene and the budget', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&scene=metal&budget=acceptable&cost=static`);
  await expect(page.locator('.sa-pick')).toContainText('a metal');
  await expect(page.locator('.sa-pick-method')).toHaveText('F82-tint (Hoffman 2019, Kutz et al. 2021)');
  await expect(page.locator('.sa-table tr.sa-recommended th')).toHaveText(/F82/);
  await openLab(page, `./embed.html?panel=${PANEL}&scene=phone-mediump`);
  await expect(page.locator('.sa-pick')).toContainText('float16 (mediump)');
});

test('a tiny benchmark fills in measured costs, is cached for the session and exports JSON', async ({ page }) => {
  test.setTimeout(120_000); // SwiftShader compiles three.js's physical shader for the frame comparison
  await openLab(page, `./embed.html?panel=${PANEL}&bench=tiny`);
  const ok = await page.evaluate((id) => window.fresnelLab.panels[id].autorun.then((r) => Boolean(r)), PANEL);
  expect(ok).toBe(true);
  const results = await page.evaluate((id) => window.fresnelLab.panels[id].resultsJson(), PANEL);
  expect(results.device.renderer).toBeTruthy();
  expect(results.device.timer).toMatch(/EXT_disjoint_timer_query_webgl2|wall clock/);
  expect(results.device.gpuError).toBeNull();
  for (const m of results.methods) {
    for (const s of [m.gpu.nsPerEval, m.gpu.mediump.nsPerEval, m.cpu.nsPerEval]) {
      expect(Number.isFinite(s.median)).toBe(true);
      expect(s.min).toBeLessThanOrEqual(s.median);
      expect(s.max).toBeGreaterThanOrEqual(s.median);
    }
  }
  expect(results.frames.spheres.msPerFrame.median).toBeGreaterThan(0);
  expect(results.frames.ratio).toBeGreaterThan(0);
  // The errors this GPU makes, read back over the default domains beside the emulated ones.
  expect(results.device.gpuReadbackError).toBeNull();
  for (const m of results.methods) {
    for (const key of ['gpuHighp', 'gpuMediump']) {
      expect(Number.isFinite(m.error[key].max), `${m.id} ${key}`).toBe(true);
      expect(m.error[key].mean).toBeLessThanOrEqual(m.error[key].max);
    }
  }
  const exactCg = results.methods.find((m) => m.id === 'exact-cg').error;
  expect(Math.abs(exactCg.gpuHighp.max - exactCg.fp32.max)).toBeLessThan(1e-6);
  // The chart and the advisor now use the measured GPU costs.
  const measured = await view(page);
  expect(measured.mode).toBe('gpu');
  const byId = Object.fromEntries(results.methods.map((m) => [m.id, m.gpu.nsPerEval.median]));
  for (const r of measured.rows) expect(r.x).toBe(byId[r.id]);
  await expect(page.locator('.sa-table thead')).toContainText('GPU ns/eval');
  await expect(page.locator('.sa-device')).toContainText(results.device.renderer);
  await expect(page.locator('.sa-status')).toContainText('Done');
  // Cached for the session: a reload without ?bench shows the same numbers at once.
  await openLab(page, `./embed.html?panel=${PANEL}`);
  expect((await view(page)).mode).toBe('gpu');
  const download = page.waitForEvent('download');
  await page.locator('.sa-json').click();
  const file = await download;
  expect(file.suggestedFilename()).toBe('fresnel-lab-speed-accuracy.json');
  const saved = JSON.parse(await (await file.createReadStream()).toArray().then((b) => Buffer.concat(b).toString()));
  expect(saved.methods.map((m) => m.id)).toEqual(results.methods.map((m) => m.id));
  expect(saved.methods[0].gpu.nsPerEval).toEqual(results.methods[0].gpu.nsPerEval);
});

test('a running benchmark can be cancelled', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  await page.locator('.sa-run').click();
  await expect(page.locator('.sa-cancel')).toBeEnabled();
  await page.locator('.sa-cancel').click();
  await expect(page.locator('.sa-status')).toHaveText('Cancelled');
  await expect(page.locator('.sa-run')).toBeEnabled();
  expect(await page.evaluate((id) => window.fresnelLab.panels[id].results, PANEL)).toBeNull();
});

test('a running benchmark pauses while the panel is off screen and goes on when it is back', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  await page.evaluate(() => {
    const spacer = document.createElement('div');
    spacer.style.height = '4000px';
    document.body.prepend(spacer); // the panel is now far below the window
  });
  // The run's promise rejects when it is cancelled below; kept here, so that is no unhandled rejection.
  await page.evaluate((id) => {
    window.benchDone = window.fresnelLab.panels[id].run('tiny').then(() => 'done', (error) => error.message);
  }, PANEL);
  await expect(page.locator('.sa-status')).toContainText('Paused while the panel is off screen');
  const paused = await page.locator('.sa-progress').evaluate((p) => p.value);
  await animationFrames(page, 60); // a window of the page's own frames in which a paused run must not move
  expect(await page.locator('.sa-progress').evaluate((p) => p.value)).toBe(paused);
  expect(paused).toBeLessThan(1);
  await page.locator('.sa-run').scrollIntoViewIfNeeded();
  // Back on screen it goes on (the run to its end is the tiny-benchmark test's); then it is cancelled.
  await expect.poll(() => page.locator('.sa-progress').evaluate((p) => p.value)).toBeGreaterThan(paused);
  await expect(page.locator('.sa-status')).not.toContainText('Paused');
  await page.locator('.sa-cancel').click();
  await expect(page.locator('.sa-status')).toHaveText('Cancelled');
  expect(await page.evaluate(() => window.benchDone)).toBe('Benchmark cancelled');
});

test('"Error measured by" this GPU plots the errors read back from the GPU, and says so', async ({ page }) => {
  test.setTimeout(60_000); // SwiftShader compiles seven programs
  await openLab(page, `./embed.html?panel=${PANEL}&scene=phone-mediump`);
  const fp16 = await view(page); // the plastic domain in float16 emulation
  await openLab(page, `./embed.html?panel=${PANEL}`);
  const fp32 = await view(page); // the same domain in float32 emulation (the default)
  await choose(page, 'Error measured by', 'This GPU, highp');
  await gpuMeasured(page);
  await expect(page.locator('.sa-reason')).toContainText('measured on this GPU');
  await expect(page.locator('.sa-reason')).toContainText('this GPU in highp (read back)');
  await expect(page).toHaveURL(/errors=gpu-highp/);
  const state = await page.evaluate((id) => {
    const v = window.fresnelLab.panels[id].view;
    return { source: v.source, scene: v.scene, rows: v.rows.map((r) => ({ id: r.methodId, max: r.max, y: r.maxCodes })) };
  }, PANEL);
  expect(state.source).toBe('gpu-highp');
  const row = (rows, id) => rows.find((r) => r.id === id);

  const ids = ['exact-cg', 'schlick-pow', 'schlick-exp2'];
  const gpu = await gpuErrors(page, state.scene, ids, 'highp');
  for (const id of ids) { // every plotted point is the read-back figure
    expect(Math.abs(row(state.rows, id).max - gpu[id].max), id).toBeLessThanOrEqual(1e-12 * gpu[id].max);
    expect(Math.abs(row(state.rows, id).y - gpu[id].maxCodes), id).toBeLessThanOrEqual(1e-9 * gpu[id].maxCodes);
  }
  // The exact form on the GPU sits at float32's rounding level, as the emulation does, far below float16's.
  const exact = row(state.rows, 'exact-cg').max;
  expect(Math.abs(exact - row(fp32.rows, 'exact-cg').max)).toBeLessThan(1e-6);
  expect(exact).toBeLessThan(row(fp16.rows, 'exact-cg').max / 100);
  // The GPU's pow and exp2 are not the emulation's (SwiftShader's pow is 2e-7 off it): where they
  // differ, the chart shows the GPU's figure, not the JavaScript one.
  const differ = ids.filter((id) => row(state.rows, id).max !== row(fp32.rows, id).max);
  expect(differ.length).toBeGreaterThan(0);
  for (const id of differ) expect(row(state.rows, id).y).not.toBe(row(fp32.rows, id).y);

  await expect(page.locator('.sa-table caption')).toContainText('this GPU\'s highp');
  await expect(page.locator('.panel-description')).toContainText('with errors measured on this GPU in highp');
  const csv = await page.evaluate((id) => window.fresnelLab.panels[id].csv(), PANEL);
  expect(csv.filename).toBe('speed-accuracy-plastic-gpu-highp.csv');
  expect(new Set(csv.columns.error_source)).toEqual(new Set(['gpu-highp']));
  expect(csv.columns.max_abs_error[csv.columns.method.indexOf('schlick-pow')]).toBe(row(state.rows, 'schlick-pow').max);
  // Back to the emulation: the JavaScript numbers again, and the CSV says so.
  await choose(page, 'Error measured by', 'JS emulation');
  expect((await view(page)).rows).toEqual(fp32.rows);
  expect((await page.evaluate((id) => window.fresnelLab.panels[id].csv(), PANEL)).columns.error_source[0]).toBe('js-fp32');
  await expect(page.locator('.sa-reason')).toContainText('JavaScript emulation of float32');
});

test('the error source comes from the URL; mediump on this GPU is measured and said beside the control', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&scene=metal&errors=gpu-mediump`);
  await gpuMeasured(page);
  await expect(sourceOption(page)).toHaveText('This GPU, mediump');
  await expect(page.locator('.sa-pick')).toContainText('this GPU\'s mediump');
  const state = await page.evaluate((id) => window.fresnelLab.panels[id].view, PANEL);
  expect(state.source).toBe('gpu-mediump');
  expect(state.rows.map((r) => r.methodId).sort()).toEqual([...CONDUCTORS].sort());
  const note = page.locator('.sa-gui-note');
  await expect(note).toBeVisible();
  await expect(note).toContainText(/mediump runs at (full|reduced) precision on this GPU: \d+ significand bits measured/);
  // The browser tests render with SwiftShader (playwright.config.js), which runs mediump as float32:
  // then the exact form's read-back error is float32's (~2e-7), well below what float16 rounding
  // alone gives (its half ulp at 1 is 2^-12 = 2.4e-4).
  await expect(note).toContainText('mediump runs at full precision on this GPU: 24 significand bits measured');
  expect(state.rows.find((r) => r.methodId === 'conductor-exact').max).toBeLessThan(1e-5);
  await expect(page.locator('.panel-description')).toContainText('mediump runs at full precision on this GPU');
});

test('a bad error source in the link falls back to the JS emulation with a notice', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&errors=cuda`);
  await expect(page.locator('.notice')).toContainText('errors=cuda is not one of js, gpu-highp, gpu-mediump; using js');
  expect((await page.evaluate((id) => window.fresnelLab.panels[id].view.source, PANEL))).toBe('js');
  expect(await page.evaluate((id) => window.fresnelLab.panels[id].gpuMeasurement, PANEL)).toBeNull();
});

test('without float render targets the GPU source says why and falls back to the JS emulation', async ({ page }) => {
  await page.addInitScript(() => {
    const original = WebGL2RenderingContext.prototype.getExtension;
    WebGL2RenderingContext.prototype.getExtension = function getExtension(name) {
      return name === 'EXT_color_buffer_float' ? null : original.call(this, name);
    };
  });
  await openLab(page, `./embed.html?panel=${PANEL}&errors=gpu-highp`);
  const source = page.locator('.sa-source');
  await expect(source).toBeVisible();
  await expect(source).toContainText('cannot render to float32 textures');
  await expect(source).toContainText('JavaScript emulation');
  expect((await view(page)).rows.find((r) => r.id === 'schlick-mul').y).toBeCloseTo(12.07, 1);
  expect(await page.evaluate((id) => window.fresnelLab.panels[id].view.source, PANEL)).toBe('js');
  await expect(sourceOption(page)).toHaveText('JS emulation');
  await expect(page.locator('.sa-reason')).toContainText('JavaScript emulation');
  await expect(page).not.toHaveURL(/errors=/);
});

test.describe('a refused shader', () => {
  test.use({ allowedErrors: /did not compile/ }); // the refusal's whole log goes to the console

  test('a shader this GPU refuses is named as the cause, not float render targets', async ({ page }) => {
    await page.addInitScript(() => {
      const status = WebGL2RenderingContext.prototype.getShaderParameter;
      WebGL2RenderingContext.prototype.getShaderParameter = function getShaderParameter(shader, name) {
        const refused = name === this.COMPILE_STATUS && this.getShaderSource(shader).includes('fm_evaluate');
        return refused ? false : status.call(this, shader, name);
      };
      const log = WebGL2RenderingContext.prototype.getShaderInfoLog;
      WebGL2RenderingContext.prototype.getShaderInfoLog = function getShaderInfoLog(shader) {
        const refused = this.getShaderSource(shader).includes('fm_evaluate');
        return refused ? 'ERROR: 0:7: \'fm_evaluate\' : stand-in refusal\n' : log.call(this, shader);
      };
    });
    await openLab(page, `./embed.html?panel=${PANEL}&errors=gpu-highp`);
    const source = page.locator('.sa-source');
    await expect(source).toBeVisible();
    await expect(source).toHaveText('This GPU could not compile the shader that evaluates a method, so the errors shown are the JavaScript '
      + 'emulation. The driver said: ERROR: 0:7: \'fm_evaluate\' : stand-in refusal');
    await expect(source).toHaveClass(/sa-source-warning/);
    expect(await page.evaluate((id) => window.fresnelLab.panels[id].view.source, PANEL)).toBe('js');
    await expect(sourceOption(page)).toHaveText('JS emulation');
  });
});
