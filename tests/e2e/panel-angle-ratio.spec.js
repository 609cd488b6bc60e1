import { test, expect, openLab } from './fixtures.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const panel = (page) => page.locator('.angle-ratio-panel');
const rValue = (page) => panel(page).locator('.ar-bar-r .ar-bar-value');
const tValue = (page) => panel(page).locator('.ar-bar-t .ar-bar-value');
const refracted = (page) => panel(page).locator('.ar-refracted');
const bandWidth = (page, cls) => panel(page).locator(`.${cls} .ar-band`).getAttribute('stroke-width');

test('mounts alone, and R from air into glass is 0.0400 at 0° and 0.3877 at 80°', async ({ page }) => {
  await openLab(page, './embed.html?panel=angle-ratio&theta=0');
  await expect(panel(page).locator('svg.ar-svg')).toBeVisible();
  await expect(rValue(page)).toHaveText('0.0400');
  await expect(tValue(page)).toHaveText('0.9600');
  // Stroke widths carry the powers: 30 units for the incident ray, 30·R and 30·T for the others.
  expect(Number(await bandWidth(page, 'ar-reflected'))).toBeCloseTo(1.2, 3);
  expect(Number(await bandWidth(page, 'ar-refracted'))).toBeCloseTo(28.8, 3);
  await openLab(page, './embed.html?panel=angle-ratio&theta=80');
  await expect(rValue(page)).toHaveText('0.3877');
  await expect(tValue(page)).toHaveText('0.6123');
  await expect(page.locator('.panel-description')).toContainText('R = 0.3877');
});

test('glass to air: the refracted ray disappears past the critical angle', async ({ page }) => {
  await openLab(page, './embed.html?panel=angle-ratio&nI=1.5&nT=1&theta=41');
  await expect(refracted(page)).toBeVisible();
  await expect(panel(page).locator('.ar-status')).toContainText('Critical angle 41.81°');
  await page.evaluate(() => window.fresnelLab.hosts['angle-ratio'].set({ theta: 42 }));
  await expect(refracted(page)).toBeHidden();
  await expect(tValue(page)).toHaveText('0.0000');
  await expect(rValue(page)).toHaveText('1.0000');
  await expect(panel(page).locator('.ar-status')).toContainText('no refracted ray and T = 0');
  await expect(panel(page).locator('.ar-tir')).toContainText('past the critical angle 41.81°');
});

test('the keyboard, a drag and the controls change the angle and the rays', async ({ page }) => {
  await openLab(page, './embed.html?panel=angle-ratio');
  const handle = panel(page).locator('.ar-handle');
  await expect(handle).toHaveAttribute('aria-valuenow', '45.0');
  await handle.focus();
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowUp');
  await expect(handle).toHaveAttribute('aria-valuenow', '51.0');
  await expect(page).toHaveURL(/theta=51(&|$)/);
  await page.keyboard.press('End');
  await expect(rValue(page)).toHaveText('1.0000');

  // Drag the ray's end to 30° from the normal (a point on that line, in the SVG's own units).
  const target = await page.evaluate(() => {
    const svg = document.querySelector('.ar-svg');
    const m = svg.getScreenCTM();
    const a = (30 * Math.PI) / 180;
    const at = (r) => new DOMPoint(400 - r * Math.sin(a), 290 - r * Math.cos(a)).matrixTransform(m);
    return at(150);
  });
  const box = await handle.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(target.x, target.y, { steps: 5 });
  await page.mouse.up();
  const theta = await page.evaluate(() => window.fresnelLab.hosts['angle-ratio'].values.theta);
  expect(theta).toBeGreaterThan(29);
  expect(theta).toBeLessThan(31);

  const before = await bandWidth(page, 'ar-reflected');
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (transmitted side)' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  expect(await bandWidth(page, 'ar-reflected')).not.toBe(before);
  await expect(page).toHaveURL(/nT=2\.4/);
});

test('CSV holds R and T from 0° to 90°, and the PNG export is an image', async ({ page }) => {
  await openLab(page, './embed.html?panel=angle-ratio&nI=1.3333&nT=1');
  const table = await page.evaluate(() => window.fresnelLab.panels['angle-ratio'].csv());
  const { theta_deg: theta, R, T } = table.columns;
  expect(theta[0]).toBe(0);
  expect(theta.at(-1)).toBe(90);
  expect(R[0]).toBeCloseTo(((1.3333 - 1) / 2.3333) ** 2, 12);
  expect(T.at(-1)).toBe(0);
  await expect.poll(() => page.evaluate(() => window.fresnelLab.panels['angle-ratio'].png()?.slice(0, 22)))
    .toBe('data:image/png;base64,');
});

test('in the pseudo-locale every word is the catalogue\'s: rays, labels, slider, status, the analogy', async ({ page }) => {
  await openInPseudoLocale(page, './embed.html?panel=angle-ratio');
  expect(await panelWordsOutside(page), 'as it opens').toEqual([]);
  for (const values of [{ nI: 1.5, nT: 1, theta: 30 }, { theta: 60 }, { nI: 1.5, nT: 1.5 }]) {
    await page.evaluate((v) => window.fresnelLab.hosts['angle-ratio'].set(v), values);
    expect(await panelWordsOutside(page), JSON.stringify(values)).toEqual([]);
  }
});

test('labels 35 % longer than English still run into no other label of the diagram', async ({ page }) => {
  await openInPseudoLocale(page, './embed.html?panel=angle-ratio&nI=1.5&nT=1&theta=30');
  const overlaps = await page.evaluate(() => {
    const boxes = [...document.querySelectorAll('.ar-medium-label, .ar-ray-label')]
      .filter((t) => t.textContent && t.getClientRects().length).map((t) => ({ text: t.textContent, box: t.getBoundingClientRect() }));
    const meet = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
    return boxes.flatMap((a, i) => boxes.slice(i + 1).filter((b) => meet(a.box, b.box)).map((b) => `${a.text} | ${b.text}`));
  });
  expect(overlaps).toEqual([]);
});
