import { test, expect, openLab, typesetSettled } from './fixtures.js';
import { fresnelExact, fresnelSchlick } from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;
const worst = (page, key) => page.locator(`[data-worst="${key}"]`);
const out = (page, key) => page.locator(`[data-out="${key}"]`);

test('air to glass: R0 = 0.04 typeset, max error 0.0357 near 85°, readout at 60°', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick');
  await expect(page.locator('.sk-formulas')).toContainText('0.040000');
  await expect(worst(page, 'schlick')).toHaveText(/^0\.0357 at 8[45]\.\d\d°$/);
  const at = Number((await worst(page, 'schlick').textContent()).match(/at ([\d.]+)°/)[1]);
  expect(at).toBeGreaterThan(84);
  expect(at).toBeLessThan(86);
  await expect(worst(page, 'cosThetaT')).toContainText('same as Schlick');
  await expect(out(page, 'exact')).toHaveText(fresnelExact(Math.cos(60 * DEG), 1, 1.5).toFixed(6));
  await expect(out(page, 'schlick')).toHaveText(fresnelSchlick(Math.cos(60 * DEG), 1, 1.5).toFixed(6));
  const data = await page.evaluate(() => {
    const { plot, csv } = window.fresnelLab.panels.schlick;
    return { series: plot.plot.data.length, cosT: plot.plot.data[3].filter((v) => v !== null).length, rows: csv().columns.theta_deg.length };
  });
  expect(data.series).toBe(6);
  expect(data.cosT).toBe(0); // no Schlick-on-cos θt curve from the less dense side
  expect(data.rows).toBeGreaterThan(700);
});

test('glass to air (from the URL): 0.959 at the critical angle 41.81°, Schlick on cos θt ≈ 0.036', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick&nI=1.5&nT=1');
  await expect(worst(page, 'schlick')).toHaveText('0.9590 at 41.81°');
  const t = await worst(page, 'cosThetaT').textContent();
  const [, value, angle] = t.match(/^([\d.]+) at ([\d.]+)°$/);
  expect(Number(value)).toBeCloseTo(0.036, 3);
  expect(Number(angle)).toBeLessThan(41.82);
  expect(Number(angle)).toBeGreaterThan(41);
  const cosT = await page.evaluate(() => window.fresnelLab.panels.schlick.plot.plot.data[3].filter((v) => v !== null).length);
  expect(cosT).toBeGreaterThan(700);
  await expect(page.locator('.sk-note')).toContainText(/critical angle 41\.81°/i);
});

test('the θ and index controls change the readout, the plot and the URL', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick');
  const plot = page.locator('.sk-plot canvas');
  const before = await plot.screenshot();
  const height = async () => (await page.locator('.sk-panel').boundingBox()).height;
  await typesetSettled(page, '.sk-panel'); // the formulas' typesetting moves the layout once, before any change
  const h0 = await height();
  const theta = page.locator('.lil-gui .lil-controller', { hasText: 'θ for the readout' }).locator('input');
  await theta.fill('80');
  await theta.press('Enter');
  await expect(out(page, 'exact')).toHaveText(fresnelExact(Math.cos(80 * DEG), 1, 1.5).toFixed(6));
  await expect(page).toHaveURL(/theta=80/);
  const nT = page.locator('.lil-gui .lil-controller', { hasText: 'n_t' }).locator('input');
  await nT.fill('2.4');
  await nT.press('Enter');
  await expect(page.locator('.sk-formulas')).toContainText('0.169550');
  await expect(page).toHaveURL(/nT=2\.4/);
  expect(Buffer.compare(before, await plot.screenshot())).not.toBe(0);
  await page.locator('.lil-gui button', { hasText: 'Swap' }).click();
  await expect(page.locator('.sk-note')).toContainText('total internal reflection');
  await expect(out(page, 'schlickT')).toHaveText('1.000000');
  expect(await height()).toBe(h0); // the live text never pushes the plot around
});
