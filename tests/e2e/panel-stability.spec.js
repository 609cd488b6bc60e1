import { test, expect, openLab, expectIdle } from './fixtures.js';
import { fresnelExact } from '../../src/optics/fresnel.js';
import { methodsOfKind } from '../../src/methods/methods.js';

const embed = (query = '') => `./embed.html?panel=stability${query}`;
const CELLS = 181 * 106;
const DEG = Math.PI / 180;
const ABOVE = 1;

/**
 * Both maps as plain data: counts, and the failing cells as { theta, ratio, cls }: all of them, or
 * only those on the rows in `ratios` (a Schlick map fails at 12 000 cells: too many to ship).
 */
function readMaps(page, ratios = null) {
  return page.evaluate((rows) => {
    const { maps, pair } = window.fresnelLab.panels.stability;
    const plain = (map) => {
      if (!map) return null;
      const failures = [];
      for (let j = 0; j < map.height; j += 1) {
        if (rows && !rows.some((r) => Math.abs(map.ratio[j] - r) < 1e-9)) continue;
        for (let i = 0; i < map.width; i += 1) {
          const cls = map.cells[j * map.width + i];
          if (cls !== 0) failures.push({ theta: map.thetaDeg[i], ratio: map.ratio[j], cls });
        }
      }
      return { counts: map.counts, failures: failures.length > 2000 ? null : failures, precision: map.precision };
    };
    return { gpu: plain(maps.gpu), js: plain(maps.js), pair };
  }, ratios);
}

const setValues = (page, update) => page.evaluate((u) => window.fresnelLab.hosts.stability.set(u), update);
const themeColor = (page, name) => page.evaluate((n) => {
  const probe = document.createElement('canvas').getContext('2d');
  probe.fillStyle = getComputedStyle(document.documentElement).getPropertyValue(n).trim();
  probe.fillRect(0, 0, 1, 1);
  return [...probe.getImageData(0, 0, 1, 1).data];
}, name);
const pixel = (page, side, theta, ratio) => page.evaluate(([s, t, r]) => {
  const p = window.fresnelLab.panels.stability;
  const map = p.maps[s];
  return p.pixelAt(s, map.thetaDeg.indexOf(t), [...map.ratio].findIndex((x) => Math.abs(x - r) < 1e-9));
}, [side, theta, ratio]);
const critical = (ratio) => Math.asin(1 / ratio) / DEG;
/** Colours equal within 10 per channel (the scaled cell image may blend at cell edges). */
const same = (a, b) => a.slice(0, 3).every((v, i) => Math.abs(v - b[i]) <= 10);

test('renders every dielectric method in highp: counts on both maps; the safe exact form has no failure', async ({ page }) => {
  await openLab(page, embed());
  await expect(page.locator('.st-map[data-side="gpu"] canvas')).toBeVisible();
  for (const { id } of methodsOfKind('dielectric')) {
    await setValues(page, { method: id, precision: 'highp' });
    const { gpu, js, pair } = await readMaps(page);
    expect(pair).toEqual({ gpu: 'highp', js: 'fp32', selected: 'gpu' });
    for (const map of [gpu, js]) expect(Object.values(map.counts).reduce((a, b) => a + b, 0)).toBe(CELLS);
    await expect(page.locator('.st-map[data-side="gpu"] [data-count="fine"]')).toHaveText(String(gpu.counts.fine));
    await expect(page.locator('.st-map[data-side="js"] [data-count="aboveTolerance"]')).toHaveText(String(js.counts.aboveTolerance));
    if (id === 'exact-cg') {
      expect(gpu.failures).toEqual([]);
      expect(js.failures).toEqual([]);
    }
  }
});

test('the lecture order fails at matched media at grazing on the GPU and in JS; float16 shows a band', async ({ page }) => {
  await openLab(page, embed('&method=exact-cg-literal&precision=highp'));
  const { gpu, js } = await readMaps(page);
  expect(gpu.failures).toEqual([{ theta: 90, ratio: 1, cls: ABOVE }]); // R = 1 where the exact R is 0
  expect(js.failures).toEqual(gpu.failures);
  expect(same(await pixel(page, 'gpu', 90, 1), await themeColor(page, '--c-schlick'))).toBe(true);
  expect(same(await pixel(page, 'gpu', 45, 1), await themeColor(page, '--border'))).toBe(true);
  await setValues(page, { precision: 'fp16' });
  const half = await readMaps(page);
  expect(half.js.failures.filter((f) => f.ratio === 1).map((f) => f.theta)).toEqual([88.5, 89, 89.5, 90]);
  // The safe order at the same precision: no failure on the matched row.
  await setValues(page, { method: 'exact-cg' });
  expect((await readMaps(page)).js.failures.filter((f) => f.ratio === 1)).toEqual([]);
});

test('Schlick without TIR fails past the critical angle on the glass side; Schlick on cos θt does not', async ({ page }) => {
  await openLab(page, embed('&method=schlick-mul&precision=highp'));
  const plain = await readMaps(page, [1.5]);
  const past = (f) => f.theta > critical(1.5) && f.theta < 90;
  const expected = Array.from({ length: 181 }, (_, i) => i / 2).filter((t) => t > critical(1.5) && t < 90);
  expect(plain.gpu.failures.filter(past).map((f) => f.theta)).toEqual(expected);
  expect(same(await pixel(page, 'gpu', 60, 1.5), await themeColor(page, '--c-schlick'))).toBe(true);
  await setValues(page, { method: 'schlick-tir' });
  const tir = await readMaps(page, [1.5]);
  expect(tir.gpu.failures.filter((f) => f.theta > critical(1.5) + 0.5)).toEqual([]);
  expect(same(await pixel(page, 'gpu', 60, 1.5), await themeColor(page, '--border'))).toBe(true);
});

test('the exact forms in mediump fail near the critical angle (on this GPU, or in float16 where mediump is full precision)', async ({
  page,
}) => {
  await openLab(page, embed()); // default: exact c/g in mediump
  const probe = await page.evaluate(() => window.fresnelLab.panels.stability.precisionProbe);
  for (const method of ['exact-cg', 'exact-sp']) {
    await setValues(page, { method, precision: 'mediump' });
    const { gpu, js, pair } = await readMaps(page);
    expect(pair).toEqual({ gpu: 'mediump', js: 'fp16', selected: 'gpu' });
    // SwiftShader runs mediump as float32: then the float16 emulation must show the failures.
    const halfMap = probe.mediumpIsFullPrecision ? js : gpu;
    expect(halfMap.failures.length).toBeGreaterThan(50);
    for (const f of halfMap.failures) {
      expect(f.ratio).toBeGreaterThan(1);
      expect(Math.abs(f.theta - critical(f.ratio))).toBeLessThan(3);
    }
    if (probe.mediumpIsFullPrecision) {
      expect(gpu.failures).toEqual([]); // the same as highp
      await expect(page.locator('.st-note')).toContainText('mediump runs at full precision on this GPU');
      await expect(page.locator('.panel-description')).toContainText('mediump runs at full precision on this GPU');
    }
  }
});

test('hover and arrow keys probe a cell: θ, ratio, exact R and both values', async ({ page }) => {
  await openLab(page, embed('&method=schlick-mul&precision=fp32'));
  const readout = page.locator('.st-readout');
  await expect(readout).toContainText('Hover or tap a map');
  await page.evaluate(() => window.fresnelLab.panels.stability.setProbe({ i: 120, j: 5 }));
  const exact = fresnelExact(Math.cos(60 * DEG), 0.5, 1);
  await expect(readout).toContainText('θ = 60.00°, n_i/n_t = 0.500');
  await expect(readout).toContainText(`exact R = ${exact.toPrecision(6)}`);
  await expect(readout).toContainText('JS float32 (highp): ');
  const canvas = page.locator('.st-map[data-side="js"] canvas');
  await canvas.focus();
  await page.keyboard.press('ArrowRight');
  await expect(readout).toContainText('θ = 60.50°');
  await page.keyboard.press('Shift+ArrowUp');
  await expect(readout).toContainText('n_i/n_t = 0.700');
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height * 0.4);
  const cell = await page.evaluate(() => window.fresnelLab.panels.stability.probeCell);
  expect(cell.i).toBeGreaterThan(60);
  expect(cell.i).toBeLessThan(120);
});

test('URL and controls: method, precision and tolerance; CSV, description, on-demand, dispose', async ({ page }) => {
  await openLab(page, embed('&method=schlick-mul&precision=highp&tolerance=0.05'));
  const host = () => page.evaluate(() => ({ ...window.fresnelLab.hosts.stability.values }));
  expect(await host()).toEqual({ method: 'schlick-mul', precision: 'highp', tolerance: 0.05 });
  await expect(page.locator('.st-map[data-side="gpu"]')).toHaveClass(/st-selected/);
  await expect(page.locator('.st-map[data-side="gpu"] .st-map-title')).toHaveText('On this GPU · highp');
  await expect(page.locator('.st-map[data-side="gpu"] .st-chosen')).toHaveText('(chosen)');
  await expect(page.locator('.st-map[data-side="js"] .st-chosen')).toBeHidden();
  const loose = (await readMaps(page)).gpu.counts.aboveTolerance;
  await setValues(page, { tolerance: 0.001 });
  const tight = (await readMaps(page)).gpu.counts.aboveTolerance;
  expect(tight).toBeGreaterThan(loose); // a tighter tolerance flags more cells
  await page.locator('.lil-gui .lil-controller', { hasText: 'Method' }).locator('select').selectOption({ label: 'Exact s/p (Snell)' });
  await page.locator('.lil-gui .lil-controller', { hasText: 'Precision' }).locator('select').selectOption({ label: 'JS float64' });
  expect((await host()).method).toBe('exact-sp');
  await expect(page.locator('.st-map[data-side="js"] .st-map-title')).toHaveText('JavaScript · fp64');
  await expect(page.locator('.st-map[data-side="js"] .st-chosen')).toHaveText('(chosen)');
  await expect(page.locator('.st-map[data-side="gpu"] .st-chosen')).toBeHidden();
  await expect(page.locator('.st-map[data-side="js"]')).toHaveClass(/st-selected/);
  const csv = await page.evaluate(() => window.fresnelLab.panels.stability.csv());
  expect(csv.columns.class).toEqual(['fine', 'aboveTolerance', 'outOfRange', 'notFinite']);
  expect(csv.columns.js_fp64).toEqual([CELLS, 0, 0, 0]);
  expect(csv.columns.gpu_highp).toEqual([CELLS, 0, 0, 0]);
  await expect(page.locator('.panel-description')).toContainText(`in JavaScript float64: ${CELLS} fine, 0 with error above 0.00100`);
  // Nothing is evaluated again while nothing changes.
  await expectIdle(page, 'stability', 24);
  expect(await page.evaluate(() => window.fresnelLab.panels.stability.png())).toMatch(/^data:image\/png;base64,/);
  const live = await page.evaluate(() => {
    const before = window.fresnelLab.contexts.live;
    window.fresnelLab.hosts.stability.unmount();
    return [before, window.fresnelLab.contexts.live];
  });
  expect(live[1]).toBe(live[0] - 1);
});

test('without float render targets the GPU map says why and the JavaScript map still works', async ({ page }) => {
  await page.addInitScript(() => {
    const original = WebGL2RenderingContext.prototype.getExtension;
    WebGL2RenderingContext.prototype.getExtension = function getExtension(name) {
      return name === 'EXT_color_buffer_float' ? null : original.call(this, name);
    };
  });
  await openLab(page, embed('&method=exact-cg-literal&precision=fp32'));
  await expect(page.locator('.st-map[data-side="gpu"] .st-map-message')).toContainText('no EXT_color_buffer_float');
  await expect(page.locator('.st-map[data-side="gpu"] canvas')).toBeHidden();
  const { gpu, js } = await readMaps(page);
  expect(gpu).toBeNull();
  expect(js.failures).toEqual([{ theta: 90, ratio: 1, cls: ABOVE }]);
  // The description names the cause, in the same words as the message in place of the map.
  await expect(page.locator('.panel-description')).toContainText('no GPU map; ');
  await expect(page.locator('.panel-description')).toContainText('no EXT_color_buffer_float');
});
