import { test, expect, openLab, expectIdle, expectOneFrame, labReady } from './fixtures.js';

// Pixel probes on the three spheres. The camera looks at each sphere's centre, so the centre of
// each third of the canvas is θ = 0; the rim probe walks outward until the view angle passes 84°.
async function probes(page) {
  return page.evaluate(() => {
    const { trio } = window.fresnelLab.panels.spheres;
    const canvas = document.querySelector('[data-panel="spheres"] canvas');
    const rect = canvas.getBoundingClientRect();
    const w = rect.width / 3;
    const cy = rect.height / 2;
    let rimDx = 0;
    for (let dx = 0; dx < w / 2; dx += 0.5) {
      const hit = trio.pick(rect.left + w / 2 - dx, rect.top + cy);
      if (!hit) break;
      if (Math.acos(hit.cosTheta) > (84 * Math.PI) / 180) { rimDx = dx; break; }
    }
    const at = (i, dx) => trio.readPixel(i * w + w / 2 - dx, cy);
    return {
      rimDx,
      rimTheta: (Math.acos(trio.pick(rect.left + w / 2 - rimDx, rect.top + cy).cosTheta) * 180) / Math.PI,
      centre: [0, 1, 2].map((i) => at(i, 0)),
      rim: [0, 1, 2].map((i) => at(i, rimDx)),
    };
  });
}

const diff = (a, b) => a.slice(0, 3).reduce((sum, v, i) => sum + Math.abs(v - b[i]), 0);

test('the hero loads with WebGL2 and no console errors', async ({ page }) => {
  await openLab(page);
  await expect(page.locator('section[data-panel="spheres"] .stage-canvas')).toBeVisible();
  await expect(page.locator('.summary')).toContainText('R0');
  await expect(page.locator('.summary')).toContainText('0.04000');
  await expect(page.locator('.summary')).toContainText('56.31°');
});

test('for n = 1.5 the spheres agree at the centre and differ at the rim', async ({ page }) => {
  await openLab(page, './?nI=1&nT=1.5');
  const p = await probes(page);
  expect(p.rimDx).toBeGreaterThan(0);
  expect(p.rimTheta).toBeGreaterThan(84);
  expect(diff(p.centre[0], p.centre[1])).toBeLessThanOrEqual(1);
  expect(diff(p.rim[0], p.rim[1])).toBeGreaterThanOrEqual(3);
  // The heatmap is dark where they agree and bright where they part.
  expect(Math.max(...p.centre[2].slice(0, 3))).toBeLessThan(12);
  expect(diff(p.rim[2], p.centre[2])).toBeGreaterThan(100);
});

test('hovering a sphere marks its θ and reads out the values there', async ({ page }) => {
  await openLab(page);
  const box = await page.locator('section[data-panel="spheres"] .stage-canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 6, box.y + box.height / 2);
  await expect(page.locator('.readout')).toContainText('θ = 0.');
  await expect(page.locator('.readout')).toContainText('F exact = 0.0400');
  await page.mouse.move(box.x + 4, box.y + 4); // the sky: no sphere under the cursor
  await expect(page.locator('.readout')).toContainText('Hover or tap a sphere');
});

test('the plot redraws when n_t changes in the controls', async ({ page }) => {
  await openLab(page);
  const plot = page.locator('.plot canvas');
  const before = await plot.screenshot();
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (sphere)' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  await expect(page.locator('.summary')).toContainText('0.16955');
  const r0 = await page.evaluate(() => window.fresnelLab.panels.spheres.plot.plot.data[1][0]);
  expect(r0).toBeCloseTo(((2.4 - 1) / (2.4 + 1)) ** 2, 12);
  expect(Buffer.compare(before, await plot.screenshot())).not.toBe(0);
});

test('a URL round trip restores the controls', async ({ page }) => {
  await openLab(page);
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (sphere)' }).locator('input');
  await input.fill('1.333');
  await input.press('Enter');
  await page.locator('.lil-gui button', { hasText: 'Swap' }).click();
  await expect(page).toHaveURL(/nI=1\.333/);
  await expect(page).toHaveURL(/nT=1(&|$)/);
  const url = page.url();
  await page.goto('about:blank');
  await openLab(page, url);
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts.spheres.values }));
  expect(values.nI).toBe(1.333);
  expect(values.nT).toBe(1);
  await expect(page.locator('.lil-gui .lil-controller', { hasText: 'n_i (incident side)' }).locator('input')).toHaveValue('1.333');
  await expect(page.locator('.summary')).toContainText('48.61°'); // critical angle, water to air
});

test('bad values in the URL fall back to defaults and say so', async ({ page }) => {
  await openLab(page, './?nT=abc&nI=9&kd=red');
  const notice = page.locator('.notice');
  await expect(notice).toBeVisible();
  await expect(notice).toContainText('nT=abc is not a number; using 1.5');
  await expect(notice).toContainText('nI=9 is outside 1 to 3; using 1');
  await expect(notice).toContainText('kd=red');
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts.spheres.values }));
  expect(values).toMatchObject({ nI: 1, nT: 1.5, kd: '#a3241c' });
  await expect(page.locator('section[data-panel="spheres"] .stage-canvas')).toBeVisible();
});

test('nothing draws while nothing changes; a change draws once', async ({ page }) => {
  await openLab(page);
  const idle = await expectIdle(page, 'spheres', 60);
  await page.evaluate(() => { window.fresnelLab.hosts.spheres.set({ nT: 1.7, env: 0.5 }); });
  await expectOneFrame(page, 'spheres', idle);
});

test('without WebGL2 the page says so and the plot still works', async ({ page }) => {
  await page.addInitScript(() => {
    const original = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function getContext(type, ...rest) {
      return type === 'webgl2' ? null : original.call(this, type, ...rest);
    };
  });
  await page.goto('./');
  await labReady(page);
  const hero = page.locator('section[data-panel="spheres"]');
  await expect(hero.locator('.stage-message')).toContainText('WebGL2');
  await expect(hero.locator('.stage-canvas')).toBeHidden(); // the message replaces the picture
  await expect(hero.locator('.plot canvas')).toBeVisible();
  await expect(hero.locator('.summary')).toContainText('0.04000');
  // The two-sphere stage falls back the same way: no blank canvas, no labels over nothing.
  await page.goto('./embed.html?panel=fresnel-lighting');
  await labReady(page);
  await expect(page.locator('.stage-message')).toContainText('The spheres need WebGL2');
  await expect(page.locator('.twin-stage-canvas')).toBeHidden();
  await expect(page.locator('.twin-stage-labels')).toBeHidden();
  await expect(page.locator('.fl-summary')).toContainText('0.0400');
});

test('an embed shows one panel, and an unknown id lists the valid ones', async ({ page }) => {
  await openLab(page, './embed.html?panel=spheres&nT=2.4');
  await expect(page.locator('.site-header')).toHaveCount(0);
  await expect(page.locator('.summary')).toContainText('0.16955');
  await page.goto('./embed.html?panel=nope');
  await expect(page.locator('.notice')).toContainText('no panel called “nope”');
  await expect(page.locator('.notice')).toContainText('spheres');
});
