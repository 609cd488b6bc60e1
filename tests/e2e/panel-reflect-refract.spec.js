import { test, expect, openLab, expectIdle, expectOneFrame } from './fixtures.js';
import { fresnelExact } from '../../src/optics/fresnel.js';
import { expectCachedTerms } from './cachedTerms.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const PANEL = 'reflect-refract';
const DEG = Math.PI / 180;
const srgb = (c) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055));
const dist = (a, b) => a.slice(0, 3).reduce((sum, v, i) => sum + Math.abs(v - b[i]), 0);

/** Sets values through the host (as a control or a message would) and reads the centre pixel. */
async function centre(page, update) {
  return page.evaluate(([id, values]) => {
    window.fresnelLab.hosts[id].set(values);
    const { view } = window.fresnelLab.panels[id];
    const rect = view.canvas.getBoundingClientRect();
    return view.readPixel(rect.width / 2, rect.height / 2);
  }, [PANEL, update]);
}

test('mounts in an embed with the centre-ray numbers', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  await expect(page.locator('.rr-canvas')).toBeVisible();
  await expect(page.locator('.rr-canvas')).toHaveAttribute('aria-label', /water surface/);
  const r30 = fresnelExact(Math.cos(60 * DEG), 1, 1.333);
  await expect(page.locator('.rr-summary')).toContainText(`R = ${r30.toFixed(4)}`);
  await expect(page.locator('.rr-summary')).toContainText('θ = 60.00°');
  await expect(page.locator('.panel-description')).toContainText(`R = ${r30.toFixed(4)}`);
});

test('80° from the normal on water reflects R = 0.3479 (URL honoured)', async ({ page }) => {
  const R = fresnelExact(Math.cos(80 * DEG), 1, 1.333);
  expect(Math.abs(R - 0.3479)).toBeLessThan(0.001);
  await openLab(page, `./embed.html?panel=${PANEL}&elevation=10`);
  const summary = page.locator('.rr-summary');
  await expect(summary).toContainText('θ = 80.00°');
  await expect(summary).toContainText(`R = ${R.toFixed(4)}`);
  await expect(summary).toContainText(`T = 1 − R = ${(1 - R).toFixed(4)}`);
  await expect(summary).toContainText('θt = 47.63°'); // asin(sin 80° / 1.333)
  await expect(page.locator('.rr-bands li[aria-current]')).toHaveText('some reflection');
});

test('steep views show the floor, grazing views the sky', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  // Straight down onto the middle of the cream tile: the refracted term is exactly (1 − R0)/n²·tile,
  // the floor's radiance spread into the wider cone above the water.
  const R0 = fresnelExact(1, 1, 1.333);
  const tile = await page.evaluate((id) => window.fresnelLab.panels[id].view.uniforms.uTileA.value, PANEL);
  const onlyFloor = await centre(page, { elevation: 90, layer: 'refracted' });
  expect(dist(onlyFloor, tile.map((c) => srgb(((1 - R0) / 1.333 ** 2) * c)))).toBeLessThanOrEqual(4);
  await expect(page.locator('.rr-summary')).toContainText(`T/n_t² = ${((1 - R0) / 1.333 ** 2).toFixed(4)}`);
  const onlySky = await centre(page, { layer: 'reflected' });
  const steep = await centre(page, { layer: 'both' });
  expect(dist(steep, onlyFloor)).toBeLessThan(dist(steep, onlySky));
  expect(steep[0]).toBeGreaterThan(steep[2] + 40); // warm floor, not blue sky
  await expect(page.locator('.rr-bands li[aria-current]')).toHaveText('little reflection');

  const grazingFloor = await centre(page, { elevation: 2, layer: 'refracted' });
  const grazingSky = await centre(page, { layer: 'reflected' });
  const grazing = await centre(page, { layer: 'both' });
  expect(dist(grazing, grazingSky)).toBeLessThan(dist(grazing, grazingFloor));
  expect(grazingSky[2]).toBeGreaterThan(grazingFloor[2] + 60);
  expect(grazing[2]).toBeGreaterThan(grazing[0]); // blue wins at grazing
  await expect(page.locator('.rr-bands li[aria-current]')).toHaveText('lots of reflection');
  await expect(page.locator('.rr-caption')).toHaveText('lots of reflection');
});

test('the glass preset and the n control change numbers and picture', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&elevation=90&layer=reflected`);
  await expect(page.locator('.rr-summary')).toContainText('R = 0.0204');
  const waterSky = await centre(page, {});
  await page.locator('.lil-gui .lil-controller', { hasText: 'Material' }).locator('select')
    .selectOption({ label: 'Glass (1.5)' });
  await expect(page.locator('.rr-summary')).toContainText('R = 0.0400');
  await expect(page).toHaveURL(/nT=1\.5/);
  const glassSky = await centre(page, {});
  expect(dist(glassSky, waterSky)).toBeGreaterThan(6); // twice the reflected sky
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (surface)' }).locator('input');
  await input.fill('2.4');
  await input.press('Enter');
  await expect(page.locator('.rr-summary')).toContainText(`R = ${fresnelExact(1, 1, 2.4).toFixed(4)}`);
  await expect(page.locator('.lil-gui .lil-controller', { hasText: 'Material' }).locator('select')).toHaveValue('Custom');
});

test('a URL with glass and a view is restored; nothing draws while idle', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&nT=1.5&elevation=45`);
  const R = fresnelExact(Math.cos(45 * DEG), 1, 1.5);
  await expect(page.locator('.rr-summary')).toContainText(`R = ${R.toFixed(4)}`);
  await expect(page.locator('.lil-gui .lil-controller', { hasText: 'Material' }).locator('select')).toHaveValue('Glass (1.5)');
  const idle = await expectIdle(page, PANEL);
  await page.evaluate((id) => window.fresnelLab.hosts[id].set({ elevation: 20, depth: 3 }), PANEL);
  await expectOneFrame(page, PANEL, idle);
});

test('n, the depth and the layer redraw over the sky kept from the view, and the picture is the one-pass picture', async ({ page, browser }) => {
  await expectCachedTerms(page, browser, {
    id: PANEL, url: `./embed.html?panel=${PANEL}&elevation=25`,
    changes: [{ nT: 1.5, depth: 2.5 }, { layer: 'refracted' }, { layer: 'both' }], live: { nT: 1.4 }, view: { elevation: 40 },
  });
});

test('in the pseudo-locale every word is the catalogue\'s: captions, key numbers, the note, description', async ({ page }) => {
  await openInPseudoLocale(page, `./embed.html?panel=${PANEL}`);
  expect(await panelWordsOutside(page), 'as it opens').toEqual([]);
  // An index no preset has shows the presets' "Custom" (src/panels/shared/indexPresets.js): not this panel's word.
  const shared = (found) => found.filter((f) => f !== 'div.lil-display: Custom');
  for (const values of [{ nT: 2.4 }, { nT: 1 }, { nT: 1.5, elevation: 2 }]) {
    await page.evaluate(([id, v]) => window.fresnelLab.hosts[id].set(v), [PANEL, values]);
    expect(shared(await panelWordsOutside(page)), JSON.stringify(values)).toEqual([]);
  }
});
