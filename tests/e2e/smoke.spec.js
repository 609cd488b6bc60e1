// The quick pass of `npm run test:smoke`: the lecture page with every panel mounted, and every
// panel alone in its embed, each drawn (or plotted) and described, with no error in the console
// (the fixture fails on one). What it cannot see, the full suite does (`npm test`), which leaves this
// pass out: a11y.spec.js mounts every panel of the lecture page, embeds.spec.js every embed.
import { test, expect, openLab } from './fixtures.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';

test('the lecture page mounts every panel as it comes into view, with no notice of a fault', async ({ page }) => {
  test.setTimeout(120_000);
  await openLab(page, './');
  await expect(page.locator('main > .notice-error')).toHaveCount(0);
  for (const id of PANEL_IDS) {
    await page.locator(`section[data-panel="${id}"]`).scrollIntoViewIfNeeded();
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].mounted, id), { message: id }).toBe(true);
    await expect(page.locator(`section[data-panel="${id}"] .panel-description`)).toHaveText(/\d/);
  }
  await expect(page.locator('.notice-error')).toHaveCount(0);
});

test('every panel mounts alone in its embed and describes itself', async ({ page }) => {
  test.setTimeout(150_000);
  for (const id of PANEL_IDS) {
    await openLab(page, `./embed.html?panel=${id}`);
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid]?.mounted ?? false, id), { message: id }).toBe(true);
    await expect(page.locator('.panel-description'), id).toHaveText(/\d/);
    await expect(page.locator('.notice-error'), id).toHaveCount(0);
  }
});
