import { test, expect, openLab } from './fixtures.js';
import { expectCachedTerms } from './cachedTerms.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const EMBED = './embed.html?panel=changing-specular';
const sum = (rgb) => rgb[0] + rgb[1] + rgb[2];
const curveAt = (page, name, elevation) => page.evaluate(
  ([n, e]) => window.fresnelLab.panels['changing-specular'].curveAt(n, e), [name, elevation],
);
// The centre of each half of the canvas: the mirror point when the view follows the light.
const centres = (page) => page.evaluate(() => {
  const { view } = window.fresnelLab.panels['changing-specular'];
  const rect = document.querySelector('.cspec-canvas').getBoundingClientRect();
  return [view.readPixel(rect.width / 4, rect.height / 2), view.readPixel((3 * rect.width) / 4, rect.height / 2)];
});

test('mounts in an embed; the plot shows Phong flat and Phong × F rising towards grazing', async ({ page }) => {
  await openLab(page, EMBED);
  await expect(page.locator('.cspec-canvas')).toBeVisible();
  await expect(page.locator('.cspec-plot canvas')).toBeVisible();
  const plotted = await page.evaluate(() => window.fresnelLab.panels['changing-specular'].plot.data.length);
  expect(plotted).toBe(3);
  expect(await curveAt(page, 'phongF', 5)).toBeGreaterThan(await curveAt(page, 'phongF', 80));
  expect(await curveAt(page, 'phong', 5)).toBe(await curveAt(page, 'phong', 80));
  expect(await curveAt(page, 'phong', 80)).toBeCloseTo(0.04, 12);
  await expect(page.locator('.panel-description')).toContainText('plain Phong is 0.0400 at every elevation');
});

test('near grazing the F side is brighter; overhead the two sides match', async ({ page }) => {
  await openLab(page, `${EMBED}&lightEl=5`);
  const [phongLow, fresnelLow] = await centres(page);
  expect(sum(fresnelLow)).toBeGreaterThan(sum(phongLow) + 150);
  await page.evaluate(() => window.fresnelLab.hosts['changing-specular'].set({ lightEl: 85 }));
  const [phongHigh, fresnelHigh] = await centres(page);
  expect(Math.abs(sum(fresnelHigh) - sum(phongHigh))).toBeLessThanOrEqual(6); // F(5°) equals R0 to four digits
});

test('changing n in the controls changes the F curve and the formulas', async ({ page }) => {
  await openLab(page, EMBED);
  const before = await curveAt(page, 'phongF', 5);
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (surface)' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  await expect(page.locator('.cspec-tex-phong')).toContainText('0.1696');
  const after = await curveAt(page, 'phongF', 5);
  expect(after).not.toBeCloseTo(before, 3);
  await expect(page).toHaveURL(/nT=2\.4/);
});

test('URL parameters are honoured and the view follows the light when linked', async ({ page }) => {
  await openLab(page, `${EMBED}&lightEl=10&s=120&nT=1.333`);
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts['changing-specular'].values }));
  expect(values).toMatchObject({ lightEl: 10, viewEl: 10, linked: true, s: 120, nT: 1.333 });
  await expect(page.locator('.cspec-tex-fresnel')).toContainText('F(80.0∘)');
  await expect(page.locator('.lil-gui .lil-controller', { hasText: 'View elevation' }).locator('input')).toHaveValue('10');
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'Light elevation' }).locator('input');
  await input.fill('40');
  await input.press('Enter');
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts['changing-specular'].values.viewEl)).toBe(40);
  await expect(page).toHaveURL(/viewEl=40/);
});

test('unlinked, the view leaves the mirror direction and the highlight falls with v·r', async ({ page }) => {
  await openLab(page, `${EMBED}&linked=false&lightEl=30&viewEl=45&s=20`);
  const h = await page.evaluate(() => window.fresnelLab.panels['changing-specular'].highlight);
  expect(h.vDotR).toBeCloseTo(Math.cos((15 * Math.PI) / 180), 12);
  expect(h.phong).toBeCloseTo(h.R0 * h.vDotR ** 20, 12);
  const csv = await page.evaluate(() => window.fresnelLab.panels['changing-specular'].csv());
  expect(Object.keys(csv.columns)).toEqual(['elevation_deg', 'phong_ks_R0', 'phong_times_F']);
  expect(csv.columns.elevation_deg).toHaveLength(181);
});

test('dispose frees the WebGL context and a remount works', async ({ page }) => {
  await openLab(page, EMBED);
  const live = await page.evaluate(() => {
    const host = window.fresnelLab.hosts['changing-specular'];
    const before = window.fresnelLab.contexts.live;
    host.unmount();
    const after = window.fresnelLab.contexts.live;
    host.mount();
    return [before, after, window.fresnelLab.contexts.live];
  });
  expect(live).toEqual([1, 0, 1]);
  await expect(page.locator('.cspec-plot canvas')).toHaveCount(1);
});

test('n redraws k alone over the terms kept from the view, and the picture is the one-pass picture', async ({ page, browser }) => {
  await expectCachedTerms(page, browser, {
    id: 'changing-specular', url: `${EMBED}&lightEl=20`, changes: [{ nT: 1.7 }, { s: 20, nT: 1.33 }], live: { nT: 1.5 }, view: { lightEl: 35 },
  });
});

test('a live formula keeps its nodes when only its numbers change, and reads as a fresh typeset would', async ({ page }) => {
  await openLab(page, EMBED);
  await page.waitForFunction(() => document.querySelector('.cspec-tex-fresnel .katex-html'));
  const html = (p) => p.evaluate(() => document.querySelector('.cspec-tex-fresnel').innerHTML);
  const kept = await page.evaluate(() => {
    const before = document.querySelector('.cspec-tex-fresnel .katex-html');
    window.fresnelLab.hosts['changing-specular'].set({ nT: 1.7 });
    return before === document.querySelector('.cspec-tex-fresnel .katex-html');
  });
  expect(kept).toBe(true);
  const phongF = await page.evaluate(() => window.fresnelLab.panels['changing-specular'].highlight.phongF.toFixed(4));
  await expect(page.locator('.cspec-tex-fresnel annotation')).toContainText(`= \\mathbf{${phongF}}`);
  // Another shape (s with one digit fewer) is typeset anew.
  const patched = await html(page);
  await page.evaluate(() => window.fresnelLab.hosts['changing-specular'].set({ s: 8 }));
  const reshaped = await html(page);
  expect(reshaped).not.toBe(patched);
  // Both are what typesetting from scratch gives: a remount with the same values.
  for (const [values, expected] of [[{ s: 60 }, patched], [{ s: 8 }, reshaped]]) {
    await page.evaluate((v) => {
      const host = window.fresnelLab.hosts['changing-specular'];
      host.set(v);
      host.unmount();
      host.mount();
    }, values);
    await page.waitForFunction(() => document.querySelector('.cspec-tex-fresnel .katex-html'));
    expect(await html(page)).toBe(expected);
  }
});

test('in the pseudo-locale every word is the catalogue\'s: labels, diagram, plot, note, description', async ({ page }) => {
  await openInPseudoLocale(page, EMBED);
  expect(await panelWordsOutside(page), 'as it opens').toEqual([]);
  await page.evaluate(() => window.fresnelLab.hosts['changing-specular'].set({ nT: 1 }));
  expect(await panelWordsOutside(page), 'n_t = 1').toEqual([]);
});
