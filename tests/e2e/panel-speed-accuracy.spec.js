import { test, expect, openLab } from './fixtures.js';

const PANEL = 'speed-accuracy';
const SCHLICK = ['schlick-pow', 'schlick-mul', 'schlick-exp2', 'schlick-tir'];
const TIR_AWARE = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-tir'];
const DIELECTRICS = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-pow', 'schlick-mul', 'schlick-tir', 'schlick-exp2'];
const CONDUCTORS = ['conductor-exact', 'conductor-schlick', 'conductor-f82'];

const view = (page) => page.evaluate((id) => {
  const { rows, mode, rec } = window.fresnelLab.panels[id].view;
  return { mode, methodId: rec.methodId, rows: rows.map((r) => ({ id: r.methodId, x: r.x, y: r.maxCodes, passes: r.passes })) };
}, PANEL);

async function choose(page, label, option) {
  await page.locator('.lil-controller', { hasText: label }).locator('select').selectOption({ label: option });
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
  // The documented "acceptable" budget (5 % of the range): a Schlick variant for opaque plastic...
  await choose(page, 'Error budget', 'Acceptable: 5 % of the range (12.75 codes)');
  await expect(page.locator('.sa-pick-method')).toContainText('Schlick');
  expect(SCHLICK).toContain((await view(page)).methodId);
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
