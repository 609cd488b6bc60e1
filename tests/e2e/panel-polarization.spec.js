import { test, expect, openLab } from './fixtures.js';

const panel = (page) => page.locator('.polarization-panel');
const readout = (page) => panel(page).locator('.pol-readout');
const point = (page) => page.evaluate(() => window.fresnelLab.panels.polarization.point);

test('mounts alone: Brewster 56.31° for air to glass, where Rp reads 0.0000', async ({ page }) => {
  await openLab(page, './embed.html?panel=polarization&theta=56.31');
  await expect(panel(page).locator('.pol-plot canvas').first()).toBeVisible();
  await expect(panel(page).locator('.pol-summary')).toContainText('Brewster angle56.31°');
  await expect(panel(page).locator('.pol-summary')).toContainText('Rp = 0.0000, Rs = 0.1479');
  await expect(panel(page).locator('.pol-summary')).toContainText('none (n_i ≤ n_t)');
  await expect(readout(page)).toContainText('Rp = 0.0000');
  await expect(readout(page)).toContainText('At θ = 56.31°');
});

test('at 60° Rs > mean > Rp, and the note gives those numbers', async ({ page }) => {
  await openLab(page, './embed.html?panel=polarization');
  const { s, p, mean } = await point(page);
  expect(s).toBeGreaterThan(mean);
  expect(mean).toBeGreaterThan(p);
  await expect(readout(page)).toContainText('Rs = 0.1766');
  await expect(readout(page)).toContainText('Rp = 0.0018');
  await expect(readout(page)).toContainText('unpolarized mean = 0.0892');
  await expect(panel(page).locator('.pol-note-numbers')).toContainText('Rs = 0.1766 against the unpolarized 0.0892, 1.98 times');
  // The plotted mean is the mean of the plotted Rs and Rp.
  const data = await page.evaluate(() => window.fresnelLab.panels.polarization.plot.data);
  for (const i of [0, 100, 240, 360]) expect(data[3][i]).toBeCloseTo((data[1][i] + data[2][i]) / 2, 12);
});

test('the controls move the curves, the Brewster angle and the readout', async ({ page }) => {
  await openLab(page, './embed.html?panel=polarization');
  const plot = panel(page).locator('.pol-plot canvas').first();
  const before = await plot.screenshot();
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (transmitted side)' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  await expect(panel(page).locator('.pol-summary')).toContainText('67.38°');
  expect(Buffer.compare(before, await plot.screenshot())).not.toBe(0);
  await page.locator('.lil-gui button', { hasText: 'Read at the Brewster angle' }).click();
  await expect(readout(page)).toContainText('At θ = 67.38°');
  await expect(readout(page)).toContainText('Rp = 0.0000');
  await expect(page).toHaveURL(/theta=67\.38/);
});

test('the URL is honoured: glass to air shows the critical angle and total reflection', async ({ page }) => {
  await openLab(page, './embed.html?panel=polarization&nI=1.5&nT=1&theta=50');
  await expect(panel(page).locator('.pol-summary')).toContainText('Critical angle41.81°');
  await expect(panel(page).locator('.pol-summary')).toContainText('Brewster angle33.69°');
  await expect(readout(page)).toContainText('Rs = 1.0000   Rp = 1.0000   unpolarized mean = 1.0000');
  await expect(panel(page).locator('.pol-note-numbers')).toContainText('everything is reflected');
  const table = await page.evaluate(() => window.fresnelLab.panels.polarization.csv());
  expect(Object.keys(table.columns)).toEqual(['theta_deg', 'Rs', 'Rp', 'R_unpolarized']);
  expect(table.columns.theta_deg).toContain((Math.asin(1 / 1.5) * 180) / Math.PI);
  expect(table.columns.Rs.at(-1)).toBe(1);
  const png = await page.evaluate(() => window.fresnelLab.panels.polarization.png());
  expect(png.startsWith('data:image/png;base64,')).toBe(true);
});
