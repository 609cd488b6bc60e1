import { test, expect, openLab, typesetSettled } from './fixtures.js';
import { fresnelExact } from '../../src/optics/fresnel.js';

const DEG = Math.PI / 180;
const term = (page, key) => page.locator(`[data-term="${key}"]`);
const number = async (locator) => Number((await locator.textContent()).replace('\u2212', '-'));

test('at 60°, air to glass, every term is shown and R = 0.0892 equals fresnelExact', async ({ page }) => {
  await openLab(page, './embed.html?panel=exact-fresnel');
  await expect(page.locator('.xf-formula .katex').first()).toBeVisible();
  await expect(term(page, 'm')).toHaveText('0.666667');
  await expect(term(page, 'cos')).toHaveText('0.500000');
  await expect(term(page, 'c')).toHaveText('0.333333');
  await expect(term(page, 'g2')).toHaveText('0.666667');
  await expect(term(page, 'g')).toHaveText('0.816497');
  const r = await term(page, 'R').textContent();
  expect(Number(r).toFixed(4)).toBe('0.0892');
  expect(Number(r)).toBeCloseTo(fresnelExact(Math.cos(60 * DEG), 1, 1.5), 6);
  await expect(page.locator('[data-check="exact"]')).toHaveText(r);
  await expect(page.locator('[data-check="polarized"]')).toContainText(r);
  const f1 = await number(term(page, 'factor1'));
  const f2 = await number(term(page, 'factor2'));
  expect(0.5 * f1 * f2).toBeCloseTo(Number(r), 5);
  await expect(page.locator('.xf-status')).toContainText('g = cos θt is real');
  await expect(page.locator('.panel-description')).toContainText('R = 0.0892');
  // The plot holds the exact curve and marks θ.
  const at60 = await page.evaluate(() => {
    const { plot } = window.fresnelLab.panels['exact-fresnel'];
    const [x, y] = plot.data;
    return y[x.indexOf(60)];
  });
  expect(at60).toBeCloseTo(fresnelExact(Math.cos(60 * DEG), 1, 1.5), 14);
});

test('glass to air at 50° (from the URL): g² < 0, g imaginary, R = 1', async ({ page }) => {
  await openLab(page, './embed.html?panel=exact-fresnel&theta=50&nI=1.5&nT=1');
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts['exact-fresnel'].values }));
  expect(values).toEqual({ theta: 50, nI: 1.5, nT: 1 });
  await expect(term(page, 'g2')).toHaveText('\u22120.320354');
  await expect(term(page, 'g')).toHaveText('imaginary');
  await expect(term(page, 'R')).toHaveText('1.000000');
  await expect(page.locator('[data-check="exact"]')).toHaveText('1.000000');
  await expect(page.locator('.xf-status')).toContainText('g would be imaginary: total internal reflection');
  await expect(page.locator('.xf-status')).toContainText('returns R = 1');
});

test('the controls move the numbers and the URL; the layout stays put', async ({ page }) => {
  await openLab(page, './embed.html?panel=exact-fresnel');
  const box = () => page.locator('.xf-panel').boundingBox();
  await typesetSettled(page, '.xf-panel');
  const before = await box();
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'θ, angle' }).locator('input');
  await input.fill('30');
  await input.press('Enter');
  await expect(term(page, 'cos')).toHaveText('0.866025');
  expect(await number(term(page, 'R'))).toBeCloseTo(fresnelExact(Math.cos(30 * DEG), 1, 1.5), 6);
  await expect(page).toHaveURL(/theta=30/);
  expect(await box()).toEqual(before);
  await page.locator('.lil-gui button', { hasText: 'Swap' }).click(); // 1.5 → 1 at 30°: still below 41.8°
  await expect(term(page, 'm')).toHaveText('1.500000');
  expect(await box()).toEqual(before);
  await page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].set({ theta: 70 }));
  await expect(term(page, 'g')).toHaveText('imaginary');
  expect(await box()).toEqual(before);
});

test('matched media at 90°: the slide order gives R = 1, the code order 0', async ({ page }) => {
  await openLab(page, './embed.html?panel=exact-fresnel&nI=1.3&nT=1.3&theta=90');
  await expect(page.locator('[data-order="lecture"] td').nth(1)).toHaveText('1.000000');
  await expect(page.locator('[data-order="safe"] td').nth(1)).toHaveText('0.000000');
  await expect(page.locator('[data-order="lecture"] td').first()).toHaveText('0.000000e0');
  await expect(term(page, 'R')).toHaveText('0.000000');
  await expect(page.locator('[data-check="exact"]')).toHaveText('0.000000');
  // Away from grazing both orders agree.
  await page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].set({ theta: 89 }));
  await expect(page.locator('[data-order="lecture"] td').nth(1)).toHaveText('0.000000');
});
