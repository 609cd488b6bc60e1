// Keyboard only, at random but reproducibly (keyFuzz.js): 300 seeded presses over the lecture page,
// then no error (the fixture), no NaN or "undefined" on screen or in an accessible name, no panel
// failed, every value inside its schema. FUZZ_SEED=<n> replays a run. Also: Tab and Shift+Tab go
// round every page (focus is never trapped). Each embed gets its presses in embeds.spec.js, and the
// reduced-motion walk is in a11y.spec.js.
import { test, expect, openLab } from './fixtures.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';
import { SEED, expectSound, fuzzKeys } from './keyFuzz.js';

test(`the lecture page, 300 seeded presses (seed ${SEED})`, async ({ page }) => {
  test.setTimeout(240_000);
  await openLab(page, './');
  await page.locator('h1').first().click(); // the keys start from the page, as a reader's would
  const values = () => page.evaluate(() => JSON.stringify(Object.values(window.fresnelLab.hosts).map((h) => h.values)));
  const before = await values();
  const pressed = await fuzzKeys(page, SEED, 300);
  await expectSound(page, `lecture page after ${pressed.join(' ')}`);
  expect(await values(), 'the presses reached the controls').not.toBe(before);
});

/** Presses `key` until focus is back on the element it started from; returns how many distinct elements it met. */
async function goRound(page, key, limit) {
  const seen = new Set();
  const mark = () => page.evaluate(() => {
    const e = /** @type {HTMLElement | null} */ (document.activeElement);
    if (!e || e === document.body) return 'body';
    e.dataset.roundId ??= String(document.querySelectorAll('[data-round-id]').length);
    return e.dataset.roundId;
  });
  const first = await mark();
  for (let i = 0; i < limit; i += 1) {
    await page.keyboard.press(key);
    const now = await mark();
    if (now === first) return seen.size;
    seen.add(now);
  }
  throw new Error(`${key} never came back round after ${limit} presses (stuck among ${seen.size})`);
}

test('focus is never trapped: Tab and Shift+Tab go all the way round the lecture page and an embed with an editor', async ({ page }) => {
  test.setTimeout(240_000);
  await openLab(page, './');
  await page.locator('h1').first().click();
  await page.keyboard.press('Tab');
  const forward = await goRound(page, 'Tab', 600);
  const back = await goRound(page, 'Shift+Tab', 600);
  expect(forward).toBeGreaterThan(PANEL_IDS.length); // panels mount as Tab brings them near: at least a stop in each
  expect(back).toBeGreaterThan(PANEL_IDS.length);
  await openLab(page, 'embed.html?panel=shader-lab');
  await page.locator('.cm-content').focus();
  await page.keyboard.press('Tab');
  expect(await page.evaluate(() => Boolean(document.activeElement?.closest('.cm-content')))).toBe(false);
  expect(await goRound(page, 'Tab', 200)).toBeGreaterThan(5);
});
