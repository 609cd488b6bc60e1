// The page's language as a reader and a deck choose it: the selector on every page with page
// controls (named from the catalogue; a choice reloads the page in it and is kept in this browser),
// an embed's lang= option, and a deck's fresnel-lab:language message, which starts the panel again
// in that language as it was. The pseudo-locale en-XA shows every catalogue message ⟦bracketed⟧.
import { test, expect, labReady, typesetSettled } from './fixtures.js';
import { english, englishPanelTitle } from './englishText.js';

const BRACKETED = /^⟦[^⟦⟧]+⟧$/;
const AROUND = /^⟦.+⟧$/; // a message with another inside it (a panel's title)
const KEPT = 'fresnel-lab:language';

/**
 * Opens a page and waits for its panels. A page in another language defines window.fresnelLab
 * only once that language's words are here, which may be after the page's load event.
 */
async function openLab(page, path) {
  await page.goto(path);
  await page.waitForFunction(() => window.fresnelLab?.ready);
  await labReady(page);
}

/** The page's languages: a group named from the catalogue, a link per language, the page's own marked current. */
const selector = (page) => page.locator('.page-controls .page-languages');

test('the languages: named from the catalogue on every page, a link reloads the page in one and it is kept', async ({ page }) => {
  // A reader who chose the pseudo-locale earlier: the kept choice is the page's language.
  await page.goto('./');
  await page.evaluate((key) => localStorage.setItem(key, 'en-XA'), KEPT);
  await page.goto('./compose.html');
  const group = selector(page);
  await expect(page.getByRole('group', { name: /^⟦[^⟦⟧]+⟧$/ })).toHaveCount(1);
  await expect(group.locator('#page-languages-name')).toHaveText(BRACKETED);
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en-XA');
  // Each language by its own name, never translated; the page's own is current, not a link.
  expect(await group.locator('[lang]').evaluateAll((items) => items.map((e) => [e.textContent, e.lang, e.getAttribute('href') !== null, e.getAttribute('aria-current')])))
    .toEqual([['English', 'en', true, null], ['Español', 'es', true, null], ['[Pseudo] Énglish', 'en-XA', false, 'true']]);

  // Arrowing and tabbing through the page's controls leaves nobody's page: only following a link does.
  await group.getByRole('link', { name: 'English' }).focus();
  for (const key of ['ArrowDown', 'ArrowUp', 'Tab', 'ArrowDown']) await page.keyboard.press(key);
  expect(page.url()).not.toMatch(/[?&]lang=/);
  await group.getByRole('link', { name: 'English' }).click();
  await page.waitForURL(/[?&]lang=en(&|$)/);
  await expect(page.getByRole('group', { name: english.host.language })).toBeVisible();
  await expect(selector(page).locator('[aria-current="true"]')).toHaveText('English');
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en');
  expect(await page.evaluate((key) => localStorage.getItem(key), KEPT)).toBe('en');

  // Kept: the other pages, opened with no language in their link, speak it (they spoke en-XA before).
  for (const path of ['./homework.html', './']) {
    await page.goto(path);
    await expect(page.getByRole('group', { name: english.host.language }), path).toBeVisible();
    await expect(selector(page).locator('[aria-current="true"]'), path).toHaveText('English');
    expect(await page.evaluate(() => document.documentElement.lang), path).toBe('en');
  }
});

test('an embed with lang=en-XA speaks it: its title and its toolbar from the catalogue', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick&lang=en-XA&nT=1.7');
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en-XA');
  await expect(page.locator('h1.embed-title')).toHaveText(BRACKETED);
  expect(await page.title()).toMatch(AROUND);
  const toolbar = page.locator('.toolbar button');
  await expect(toolbar).toHaveCount(5);
  for (const text of await toolbar.allTextContents()) expect(text).toMatch(BRACKETED);
  expect(await page.evaluate(() => window.fresnelLab.hosts.schlick.values.nT)).toBe(1.7);
});

test('a deck\'s language message starts the embed again in that language, as it was', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick&nT=1.7&theme=light');
  await expect(page.locator('h1.embed-title')).toHaveText(englishPanelTitle('schlick'));
  await expect(page.locator('.toolbar button').first()).toHaveText(english.host.copyLink);
  // A language the lab does not speak changes nothing.
  await page.evaluate(() => window.postMessage({ type: 'fresnel-lab:language', lang: 'xx' }, '*'));
  // The deck changes a value and locks a control, then asks for another language at once: the
  // panel starts again as it is now, not as its link said a moment before.
  await page.evaluate(() => {
    window.postMessage({ type: 'fresnel-lab:set', params: { nT: 2.2 } }, '*');
    window.postMessage({ type: 'fresnel-lab:lock', keys: ['nI'] }, '*');
    window.postMessage({ type: 'fresnel-lab:language', lang: 'en-XA' }, '*');
  });
  await page.waitForURL(/[?&]lang=en-XA(&|$)/);
  await page.waitForFunction(() => window.fresnelLab?.ready);
  await labReady(page);
  expect(await page.evaluate(() => document.documentElement.lang)).toBe('en-XA');
  await expect(page.locator('h1.embed-title')).toHaveText(BRACKETED);
  await expect(page.locator('.toolbar button').first()).toHaveText(BRACKETED);
  expect(await page.evaluate(() => window.fresnelLab.hosts.schlick.values.nT)).toBe(2.2);
  expect(await page.evaluate(() => window.fresnelLab.hosts.schlick.locked)).toEqual(['nI']);
  expect(new URL(page.url()).searchParams.get('theme')).toBe('light'); // the embed's own options stay
});

test('a formula speaks the page\'s language: its words from the catalogue, and Spanish writes sen', async ({ page }) => {
  // What KaTeX draws (its HTML; the MathML beside it keeps the TeX source as an annotation).
  const drawn = async (selector) => {
    await typesetSettled(page, selector);
    return (await page.locator(`${selector} .katex-html`).first().textContent()).replace(/\s+/g, ' ');
  };
  await openLab(page, './embed.html?panel=refraction-waves&lang=es&nI=1.5&nT=1&angle=60&play=false'); // past the critical angle
  const snell = await drawn('.rw-snell');
  expect(snell).toContain('sen');
  expect(snell).not.toMatch(/sin/);
  expect(snell).toContain('no hay rayo refractado');
  await openLab(page, './embed.html?panel=reflect-refract&lang=es');
  for (const word of ['color', 'cielo', 'reflejado', 'fondo', 'refractado']) expect(await drawn('.rr-formula')).toContain(word);
  await openLab(page, './embed.html?panel=asphalt&lang=es');
  expect(await drawn('.asphalt-formula')).toMatch(/Lesp.*Esol/);
  await openLab(page, './embed.html?panel=refraction-waves&nI=1.5&nT=1&angle=60&play=false');
  expect(await drawn('.rw-snell')).toMatch(/sin.*no refracted ray/);
});
