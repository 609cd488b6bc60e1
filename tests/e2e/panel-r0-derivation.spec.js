import { test, expect, openLab } from './fixtures.js';

const lineValues = (page) => page.locator('.r0-lines .r0-value').allTextContents();

test('air to glass: every line of the derivation shows 0.040000', async ({ page }) => {
  await openLab(page, './embed.html?panel=r0-derivation');
  await expect(page.locator('.r0-lines .katex')).toHaveCount(18); // "=" and the expression, 9 lines
  expect(await lineValues(page)).toEqual(Array(9).fill('0.040000'));
  await expect(page.locator('.r0-setup .r0-value')).toHaveText(['0.666667', '1.000000']);
  await expect(page.locator('.r0-verdict')).toContainText('✓ All 9 lines agree');
  await expect(page.locator('.r0-refs')).toContainText('normalIncidence(n_i, n_t)0.040000');
  await expect(page.locator('.r0-refs')).toContainText('fresnelExact(cos 0° = 1, n_i, n_t)0.040000');
  await expect(page.locator('.panel-description')).toContainText('R(0°) = 0.040000');
});

test('water to air from the URL: every line shows 0.020373', async ({ page }) => {
  await openLab(page, './embed.html?panel=r0-derivation&nI=1.333&nT=1');
  expect(await lineValues(page)).toEqual(Array(9).fill('0.020373'));
  await expect(page.locator('.r0-setup .r0-value').first()).toHaveText('1.333000');
  await expect(page.locator('.r0-verdict')).toContainText('✓');
});

test('changing n_t re-evaluates every line and writes the URL', async ({ page }) => {
  await openLab(page, './embed.html?panel=r0-derivation');
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  await expect(page.locator('.r0-lines .r0-value').first()).toHaveText('0.169550');
  expect(await lineValues(page)).toEqual(Array(9).fill('0.169550'));
  await expect(page).toHaveURL(/nT=2\.4/);
  await page.locator('.lil-gui button', { hasText: 'Swap' }).click();
  expect(await lineValues(page)).toEqual(Array(9).fill('0.169550'));
  await expect(page.locator('.r0-setup .r0-value').first()).toHaveText('2.400000');
});
