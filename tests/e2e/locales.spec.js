// Browser languages the lab does not choose: every panel mounts, on the lecture page and in its
// embed, whatever the browser reports. Chromium on Linux under LANG=C.UTF-8 reports `en-US@posix`
// (the context's locale reproduces it), other setups `C` or nothing (navigator.language forced
// before any script runs): there the lecture page, then every embed on three pages, each taking its
// share in turn (much of a load is waiting, not drawing). Then valid tags of other scripts, number
// systems and directions, which no Intl call refuses: the lecture page, which loads every panel's
// module (where uPlot's refusal was) and mounts the hero. In every one, a number typed into the
// hero's control with a decimal comma is read. Per language one context.
import { test, expect, openLab } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';

// A locale of its own per language, and navigator.language forced in its context: pages of their own.
test.use({ ownPage: true });

const LANGUAGES = [
  { name: 'en-US@posix (Chromium on Linux under LANG=C.UTF-8)', locale: 'en-US@posix', embeds: true },
  { name: 'C', forced: 'C', embeds: true },
  { name: 'an empty string', forced: '', embeds: true },
  ...['de-DE', 'tr-TR', 'ar-EG', 'zh-CN', 'he'].map((locale) => ({ name: locale, locale, embeds: false })),
];
const PAGES = 3;

/** What the page says went wrong: each error notice (a panel that could not load or start), title and reasons. */
const errorNotices = (page) => page.locator('.notice-error').evaluateAll((notices) => notices
  .map((notice) => [notice.querySelector('strong'), ...notice.querySelectorAll('li')].map((part) => part?.textContent).join(' ')));

/** A further page of the context whose console errors and page errors land in `problems` (the fixture watches the first). */
async function watchedPage(context, problems) {
  const page = await context.newPage();
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  return page;
}

for (const { name, locale, forced, embeds } of LANGUAGES) {
  test.describe(`browser language ${name}`, () => {
    if (locale) test.use({ locale });

    test(embeds ? 'the lecture page and every panel\'s embed mount' : 'the lecture page mounts, every panel\'s module loaded', async ({ page }) => {
      test.setTimeout(90_000);
      const language = locale ?? forced;
      if (forced !== undefined) {
        await page.context().addInitScript((tag) => {
          Object.defineProperty(Navigator.prototype, 'language', { get: () => tag, configurable: true });
          Object.defineProperty(Navigator.prototype, 'languages', { get: () => (tag ? [tag] : []), configurable: true });
        }, forced);
      }
      // `ready` waits for every panel's module: one that failed has its notice by then.
      await openLab(page, './');
      expect(await page.evaluate(() => navigator.language), 'the language under test').toBe(language);
      expect.soft(await errorNotices(page), 'the lecture page').toEqual([]);
      // The hero is on screen: mounted by `ready`.
      expect.soft(await page.evaluate(() => window.fresnelLab.hosts.spheres.mounted), 'the hero mounted').toBe(true);
      // The other panels' modules arrive once the hero has drawn; a module that failed never loads.
      await expect.poll(() => page.evaluate(() => Object.values(window.fresnelLab.hosts).filter((h) => !h.loaded).map((h) => h.id)),
        { message: 'panels whose module did not load', timeout: 60_000 }).toEqual([]);
      expect.soft(await errorNotices(page), 'the lecture page, every module in').toEqual([]);
      // A number typed with a decimal comma is read as one, though the page is in English here.
      const nT = page.locator('.lil-gui .lil-controller', { hasText: 'n_t (sphere)' }).locator('input');
      await nT.fill('');
      await nT.pressSequentially('1,7');
      await nT.press('Enter');
      await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts.spheres.values.nT), { message: 'n_t typed as 1,7' }).toBe(1.7);
      if (!embeds) return;

      const problems = [];
      const pages = [page];
      while (pages.length < PAGES) pages.push(await watchedPage(page.context(), problems));
      await Promise.all(pages.map(async (tab, k) => {
        for (const { id, animates } of PANELS.filter((_, i) => i % PAGES === k)) {
          const still = `${animates ? `&${animates}=false` : ''}${id === 'normal-mips' ? '&truth=false' : ''}`;
          await openLab(tab, `./embed.html?panel=${id}${still}`);
          expect.soft(await tab.evaluate(() => navigator.language), `the language of the ${id} embed`).toBe(language);
          expect.soft(await errorNotices(tab), `the ${id} embed`).toEqual([]);
          expect.soft(await tab.evaluate((pid) => window.fresnelLab.hosts[pid]?.mounted ?? false, id), `${id} mounted`).toBe(true);
        }
      }));
      expect(problems, 'the other pages logged errors').toEqual([]);
    });
  });
}
