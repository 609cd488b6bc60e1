// The example deck (examples/deck.html): a real reveal.js deck with preloaded and lazily loaded
// embeds. Stepping through and back loads, pauses and resumes each panel, the WebGL contexts
// across all frames stay few, and a clicker's keys pressed inside a panel move the deck.
import { test, expect } from './fixtures.js';

const frameOf = (page, id) => page.frames().find((f) => f.url().includes(`panel=${id}`)) ?? null;

/** Live WebGL contexts summed over every embed of the deck. */
const liveContexts = async (page) => {
  let live = 0;
  for (const frame of page.frames().filter((f) => f.url().includes('embed.html'))) {
    live += await frame.evaluate(() => window.fresnelLab?.contexts.live ?? 0).catch(() => 0);
  }
  return live;
};

const mounted = async (page, id) => {
  const frame = frameOf(page, id);
  if (!frame) return null;
  return frame.evaluate((pid) => window.fresnelLab?.hosts[pid]?.mounted ?? null, id).catch(() => null);
};

async function goTo(page, index) {
  await page.evaluate((h) => window.deck.slide(h), index);
  await expect.poll(() => page.evaluate(() => window.deck.getIndices().h)).toBe(index);
}

test('stepping through the deck and back loads, pauses and resumes each panel, with few contexts', async ({ page }) => {
  test.setTimeout(120_000);
  await page.goto('./examples/deck.html');
  await page.waitForFunction(() => window.deck?.isReady());
  const peak = { live: 0 };
  const watch = async () => { peak.live = Math.max(peak.live, await liveContexts(page)); };

  await goTo(page, 1); // the hero, preloaded: it draws while its slide is shown
  await expect.poll(() => mounted(page, 'spheres')).toBe(true);
  // metals, preloaded two slides ahead and off screen, gives its view and context back.
  await expect.poll(() => frameOf(page, 'metals')?.evaluate(() => Boolean(window.fresnelLab?.hosts.metals)).catch(() => false) ?? false).toBe(true);
  await expect.poll(() => mounted(page, 'metals')).toBe(false);
  await frameOf(page, 'spheres').evaluate(() => window.fresnelLab.hosts.spheres.set({ viewAz: 55, nT: 1.9 }));
  const heroPicture = () => frameOf(page, 'spheres').evaluate(() => window.fresnelLab.panels.spheres.png());
  await expect.poll(() => frameOf(page, 'spheres').evaluate(() => window.fresnelLab.hosts.spheres.frames)).toBeGreaterThan(1);
  const before = await heroPicture();
  await watch();

  await goTo(page, 2); // Schlick, lazily loaded; the hero's slide was left: it paused
  await expect.poll(() => mounted(page, 'schlick')).toBe(true);
  await expect.poll(() => mounted(page, 'spheres')).toBe(false);
  await watch();

  await goTo(page, 3); // metals, preloaded; Schlick's frame is unloaded
  await expect.poll(() => mounted(page, 'metals')).toBe(true);
  await expect.poll(() => frameOf(page, 'schlick')).toBeNull();
  await watch();

  await goTo(page, 1); // back to the hero, two slides away at most: resumed exactly as it was left
  await expect.poll(() => mounted(page, 'spheres')).toBe(true);
  expect(await frameOf(page, 'spheres').evaluate(() => ({ ...window.fresnelLab.hosts.spheres.values }))).toMatchObject({ viewAz: 55, nT: 1.9 });
  await expect.poll(heroPicture).toBe(before);
  await expect.poll(() => mounted(page, 'metals')).toBe(false);
  await watch();

  await goTo(page, 4); // normal-mips, lazily loaded; the hero is now beyond reveal.js's viewDistance
  await expect.poll(() => mounted(page, 'normal-mips')).toBe(true);
  await expect.poll(() => frameOf(page, 'spheres')).toBeNull();
  await watch();

  await goTo(page, 1); // reloaded, so it starts from its link again
  await expect.poll(() => mounted(page, 'spheres')).toBe(true);
  expect(await frameOf(page, 'spheres').evaluate(() => window.fresnelLab.hosts.spheres.values.nT)).toBe(1.5);
  await expect.poll(() => frameOf(page, 'normal-mips')).toBeNull();
  await watch();
  expect(peak.live).toBeLessThanOrEqual(2);
});

test('a clicker\'s keys pressed inside a panel move the deck', async ({ page }) => {
  await page.goto('./examples/deck.html#/1');
  await page.waitForFunction(() => window.deck?.isReady());
  await expect.poll(() => mounted(page, 'spheres')).toBe(true);
  await page.frameLocator('iframe[src*="panel=spheres"]').locator('.embed-title').click(); // focus is in the panel now
  await page.keyboard.press('PageDown');
  await expect.poll(() => page.evaluate(() => window.deck.getIndices().h)).toBe(2);
  await expect.poll(() => mounted(page, 'schlick')).toBe(true);
  await page.frameLocator('iframe[src*="panel=schlick"]').locator('.embed-title').click();
  await page.keyboard.press('PageUp');
  await expect.poll(() => page.evaluate(() => window.deck.getIndices().h)).toBe(1);
});
