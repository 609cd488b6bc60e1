// The page's language as a reader chooses it: the selector on every page with page controls (named
// from the catalogue; a choice reloads the page in it and is kept in this browser). The
// pseudo-locale en-XA shows every catalogue message ⟦bracketed⟧.
import { test, expect } from './fixtures.js';
import { english } from './englishText.js';

const KEPT = 'fresnel-lab:language';

/** The page's language selector and the name its label gives it. */
const selector = (page) => page.locator('.page-controls label').filter({ has: page.locator('select[lang=""]') });

test('the language selector: named from the catalogue on every page, a choice reloads the page in it and is kept', async ({ page }) => {
  // A reader who chose the pseudo-locale earlier: the kept choice is the page's language.
  await page.goto('./');
  await page.evaluate((key) => localStorage.setItem(key, 'en-XA'), KEPT);
  await page.goto('./compose.html');
  const label = selector(page);
  await expect(label.locator('span')).toHaveText(/^⟦[^⟦⟧]+⟧ $/);
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en-XA');
  await expect(label.locator('select')).toHaveValue('en-XA'); // it says what the page speaks
  // Each language by its own name (its label), never translated.
  expect(await label.locator('option').evaluateAll((options) => options.map((o) => [o.value, o.label, o.lang]))).toEqual([
    ['en', 'English', 'en'], ['es', 'Español', 'es'], ['en-XA', '[Pseudo] Énglish', 'en-XA'],
  ]);

  await label.locator('select').selectOption('en');
  await page.waitForURL(/[?&]lang=en(&|$)/);
  await expect(selector(page).locator('span')).toHaveText(`${english.host.language} `);
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en');
  expect(await page.evaluate((key) => localStorage.getItem(key), KEPT)).toBe('en');

  // Kept: the other pages, opened with no language in their link, speak it (they spoke en-XA before).
  for (const path of ['./homework.html', './']) {
    await page.goto(path);
    await expect(selector(page).locator('span'), path).toHaveText(`${english.host.language} `);
    await expect(selector(page).locator('select'), path).toHaveValue('en');
    expect(await page.evaluate(() => document.documentElement.lang), path).toBe('en');
  }
});
