import { test, expect, openLab } from './fixtures.js';
import { metals } from './metalsData.js';
import { expectCachedTerms } from './cachedTerms.js';

const embed = (query = '') => `./embed.html?panel=metals${query}`;
const sum = (p) => p[0] + p[1] + p[2];
const diff = (a, b) => a.slice(0, 3).reduce((s, v, i) => s + Math.abs(v - b[i]), 0);

test('F0 swatches: gold ≈ (0.956, 0.792, 0.408); the dielectric 0.040', async ({ page }) => {
  await openLab(page, embed());
  await expect(page.locator('.twin-stage-canvas')).toBeVisible();
  const gold = page.locator('.mt-swatch[data-metal="gold"]');
  await expect(gold.locator('.mt-f0')).toHaveText('0.956 0.792 0.408');
  await expect(gold).toHaveAttribute('aria-pressed', 'true');
  await expect(page.locator('[data-material="dielectric"] .mt-f0')).toHaveText('0.040 0.040 0.040');
  await expect(page.locator('.mt-swatch[data-metal]')).toHaveCount(metals.length);
  // The chip is F0 encoded to sRGB: gold's linear 0.956, 0.792, 0.408 is about (250, 230, 171).
  const chip = await gold.locator('.mt-chip').evaluate((el) => getComputedStyle(el).backgroundColor);
  const [r, g, b] = chip.match(/\d+/g).map(Number);
  expect(Math.abs(r - 250) + Math.abs(g - 230) + Math.abs(b - 171)).toBeLessThanOrEqual(6);
  await expect(page.locator('.panel-description')).toContainText('F0 is 0.956, 0.792, 0.408');
});

test('the metal reflects most light head-on; the dielectric only a few percent', async ({ page }) => {
  await openLab(page, embed());
  const [dielectric, metal] = await page.evaluate(() => {
    const { stage } = window.fresnelLab.panels.metals;
    return [stage.readAt(0, 0), stage.readAt(1, 0)];
  });
  expect(sum(metal)).toBeGreaterThan(3 * sum(dielectric));
  expect(metal[0]).toBeGreaterThan(metal[2]); // gold: red F0 above blue
});

test("aluminium's exact red curve dips below F0 near 80°, which Schlick cannot", async ({ page }) => {
  await openLab(page, embed('&metal=aluminium'));
  const red = await page.evaluate(() => {
    const { plot } = window.fresnelLab.panels.metals;
    const [theta, exactRed, , , schlickRed] = plot.data;
    let low = 0;
    for (let i = 1; i < theta.length; i += 1) if (exactRed[i] < exactRed[low]) low = i;
    return { f0: exactRed[0], low: exactRed[low], at: theta[low], schlickMin: Math.min(...schlickRed) };
  });
  expect(red.f0).toBeCloseTo(0.9056, 4);
  expect(red.at).toBeGreaterThan(76);
  expect(red.at).toBeLessThan(86);
  expect(red.f0 - red.low).toBeGreaterThan(0.05);
  expect(red.schlickMin).toBeCloseTo(red.f0, 10); // Schlick never drops below F0
  const row = page.locator('.mt-table tbody tr').first();
  await expect(row).toContainText('0.9056');
  // The minimum off the plot's 0.25° grid (which puts it at 82.25°): 82.294° by a 1e-5° scan.
  await expect(row).toContainText('0.8262 at 82.29°');
  await expect(page.locator('.panel-description')).toContainText('dips to 0.8262');
});

test('controls: a swatch picks the metal, the toggle switches the sphere to Schlick', async ({ page }) => {
  await openLab(page, embed('&metal=aluminium'));
  const rim = () => page.evaluate(() => window.fresnelLab.panels.metals.stage.readAt(1, 83));
  const exact = await rim();
  const select = page.locator('.lil-gui .lil-controller', { hasText: 'Metal sphere uses' }).locator('select');
  await select.selectOption({ label: 'Schlick' });
  await expect(page.locator('.twin-stage-labels')).toContainText('Aluminium, Schlick');
  expect(diff(await rim(), exact)).toBeGreaterThan(10); // 0.13 brighter near 83° with Schlick
  await page.locator('.mt-swatch[data-metal="iron"]').focus();
  await page.keyboard.press('Enter');
  await expect(page.locator('.mt-swatch[data-metal="iron"]')).toHaveAttribute('aria-pressed', 'true');
  expect(await page.evaluate(() => window.fresnelLab.hosts.metals.values.metal)).toBe('iron');
  await expect(page.locator('.mt-table caption')).toContainText('Iron');
});

test('a deck that locks the metal locks its swatches too: shown, not pressable', async ({ page }) => {
  await openLab(page, embed('&metal=gold&lock=metal'));
  const silver = page.locator('.mt-swatch[data-metal="silver"]');
  await expect(silver).toBeDisabled();
  await expect(page.locator('.mt-swatch[data-metal="gold"]')).toHaveAttribute('aria-pressed', 'true');
  expect(await silver.evaluate((b) => getComputedStyle(b).cursor)).toBe('default');
  expect(await silver.evaluate((b) => getComputedStyle(b).opacity)).toBe('1'); // full contrast, from the back of the room
  await silver.click({ force: true });
  expect(await page.evaluate(() => window.fresnelLab.hosts.metals.values.metal)).toBe('gold');
  // Unlocked by the message API, they work again.
  await page.evaluate(() => window.fresnelLab.hosts.metals.controls('unlock', ['metal']));
  await expect(silver).toBeEnabled();
});

test('the URL sets the metal, the method and the dielectric index', async ({ page }) => {
  await openLab(page, embed('&metal=copper&fresnel=schlick&nT=2.4'));
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts.metals.values }));
  expect(values).toEqual({ metal: 'copper', fresnel: 'schlick', nT: 2.4 });
  await expect(page.locator('.twin-stage-labels')).toContainText('Dielectric, n = 2.4');
  await expect(page.locator('.twin-stage-labels')).toContainText('Copper, Schlick');
  await expect(page.locator('[data-material="dielectric"] .mt-f0')).toHaveText('0.170 0.170 0.170');
  await expect(page.locator('.mt-swatch[data-metal="copper"]')).toHaveAttribute('aria-pressed', 'true');
  const csv = await page.evaluate(() => window.fresnelLab.panels.metals.csv());
  expect(Object.keys(csv.columns)).toContain('schlick_blue');
  expect(csv.columns.exact_red[0]).toBeCloseTo(0.9352, 4);
  // Unmounting frees the WebGL context.
  const live = await page.evaluate(() => {
    const before = window.fresnelLab.contexts.live;
    window.fresnelLab.hosts.metals.unmount();
    return [before, window.fresnelLab.contexts.live];
  });
  expect(live[1]).toBe(live[0] - 1);
});

test('the dielectric\'s n redraws its F alone over the terms kept from the view, and the picture is the one-pass picture', async ({ page, browser }) => {
  await expectCachedTerms(page, browser, {
    id: 'metals', url: embed(), changes: [{ nT: 1.8 }, { fresnel: 'schlick', nT: 1.33 }], live: { nT: 1.6 }, view: { fresnel: 'exact' },
  });
});
