import { test, expect, openLab } from './fixtures.js';

const row = (page, id) => page.locator(`.ri-table tr[data-id="${id}"]`);
const bodyNames = (page) => page.locator('.ri-table tbody .ri-name').allTextContents();
const header = (page, key) => page.locator(`.ri-table th:has(button[data-sort="${key}"])`);

test('mounts alone with the right numbers: N-BK7 R0 0.042, water 48.6° and 0.75 c', async ({ page }) => {
  await openLab(page, './embed.html?panel=refractive-index');
  await expect(row(page, 'glass').locator('.ri-r0')).toHaveText('0.042');
  await expect(row(page, 'water').locator('.ri-critical')).toHaveText('48.6°');
  await expect(row(page, 'water')).toContainText('0.7500 c');
  await expect(row(page, 'water')).toContainText('224\u202f850 km/s');
  await expect(row(page, 'air').locator('.ri-n')).toHaveText('1.000293');
  await expect(row(page, 'diamond')).toContainText('refractiveindex.info');
  await expect(page.locator('.panel-description')).toContainText('Diamond reflects R0 = 0.172');
});

test('the header buttons sort every way, by mouse and keyboard, with aria-sort', async ({ page }) => {
  await openLab(page, './embed.html?panel=refractive-index');
  await expect(header(page, 'n')).toHaveAttribute('aria-sort', 'ascending');
  expect((await bodyNames(page)).at(-1)).toBe('Diamond');
  await page.locator('button[data-sort="n"]').click();
  await expect(header(page, 'n')).toHaveAttribute('aria-sort', 'descending');
  expect((await bodyNames(page))[0]).toBe('Diamond');
  await page.locator('button[data-sort="name"]').focus();
  await page.keyboard.press('Enter');
  await expect(header(page, 'name')).toHaveAttribute('aria-sort', 'ascending');
  await expect(header(page, 'n')).toHaveAttribute('aria-sort', 'none');
  expect((await bodyNames(page)).slice(0, 2)).toEqual(['Acrylic (PMMA)', 'Air']);
  await page.keyboard.press('Space');
  await expect(header(page, 'name')).toHaveAttribute('aria-sort', 'descending');
  await page.locator('button[data-sort="critical"]').click();
  expect((await bodyNames(page))[0]).toBe('Diamond');
  await expect(page).toHaveURL(/sort=critical/);
});

test('the custom n control computes its row live', async ({ page }) => {
  await openLab(page, './embed.html?panel=refractive-index');
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'Custom n' }).locator('input');
  await input.fill('2');
  await input.press('Enter');
  const custom = row(page, 'custom');
  await expect(custom.locator('.ri-n')).toHaveText('2.0000');
  await expect(custom.locator('.ri-r0')).toHaveText('0.111');
  await expect(custom.locator('.ri-critical')).toHaveText('30.0°');
  await expect(custom).toContainText('149\u202f900 km/s'); // c/2 to the 10 km/s the table keeps
});

test('the URL sets sorting, the selection and the custom n', async ({ page }) => {
  await openLab(page, './embed.html?panel=refractive-index&sort=r0&dir=desc&selected=ice&customN=1.7');
  await expect(header(page, 'r0')).toHaveAttribute('aria-sort', 'descending');
  expect((await bodyNames(page))[0]).toBe('Diamond');
  await expect(row(page, 'ice')).toHaveAttribute('aria-current', 'true');
  await expect(row(page, 'ice').locator('.ri-use')).toHaveAttribute('aria-pressed', 'true');
  await expect(row(page, 'custom').locator('.ri-n')).toHaveText('1.7000');
});

test('on the lecture page "Use" on water sets n in the other panels', async ({ page }) => {
  await openLab(page, './#refractive-index'); // scrolled there: only the nearby panels mount
  const section = page.locator('section[data-panel="refractive-index"]');
  await section.scrollIntoViewIfNeeded();
  const use = section.locator('tr[data-id="water"] .ri-use');
  await use.click();
  await expect(use).toHaveText('In use');
  await expect(section.locator('tr[data-id="water"]')).toHaveAttribute('aria-current', 'true');
  expect(await page.evaluate(() => window.fresnelLab.hosts.spheres.values.nT)).toBe(1.3333);
  // The neighbouring panels take it too, through the manifest's material parameter (n_t).
  const nT = await page.evaluate(() => ['angle-ratio', 'polarization'].map((id) => window.fresnelLab.hosts[id]?.values.nT));
  expect(nT).toEqual([1.3333, 1.3333]);
  await expect(page).toHaveURL(/refractive-index\.selected=water/);
  await section.locator('tr[data-id="diamond"] .ri-use').click();
  expect(await page.evaluate(() => window.fresnelLab.hosts.spheres.values.nT)).toBe(2.4166);
  await expect(section.locator('tr[data-id="water"] .ri-use')).toHaveText('Use');
});
