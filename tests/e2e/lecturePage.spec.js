// A composed lecture on the lecture page: opened from its link (and from a data element in the page,
// as the offline export writes it), its items in their order with their states and texts, stepped
// through with the clicker keys, the same panel twice kept apart in the URL and the links; a damaged
// lecture names what it refuses and opens the rest.
import { deflateSync } from 'fflate';
import { test, expect, openLab } from './fixtures.js';
import { seriousViolations } from './audit.js';
import { panelEntry } from '../../src/panels/manifest.js';

/** A lecture's link code, made here as the format says (raw DEFLATE, base64url), not by the page's own writer. */
const code = (lecture) => `L1.${Buffer.from(deflateSync(Buffer.from(JSON.stringify(lecture)), { level: 9 })).toString('base64url')}`;

const LECTURE = {
  kind: 'fresnel-lab-lecture',
  version: 1,
  title: 'Glass, both ways',
  items: [
    { type: 'panel', panel: 'spheres', state: { nT: 1.7 }, heading: 'Into the glass', text: 'Watch the *rim*: $R_0$ grows with $n_t$.' },
    { type: 'text', heading: 'Agenda', text: '1. Into the glass\n2. Out of it' },
    { type: 'panel', panel: 'spheres', state: { nI: 1.5, nT: 1 }, lock: ['nI'], heading: 'Out of the glass' },
    { type: 'question', question: 'brewster-predict', heading: 'Before Brewster' },
    { type: 'panel', panel: 'polarization', text: 'Where does R_p vanish?' },
    { type: 'panel', panel: 'schlick' },
    { type: 'panel', panel: 'r0-derivation', state: { nT: 2.4 } },
  ],
};
const KEYS = ['spheres', 'text--2', 'spheres--2', 'question--4', 'polarization', 'schlick', 'r0-derivation'];

const values = (page, key) => page.evaluate((k) => ({ ...window.fresnelLab.hosts[k].values }), key);
const nT = (page, key) => page.locator(`#${key} .lil-gui .lil-controller`, { hasText: 'n_t (sphere)' }).locator('input');

test('a composed lecture opens from its link as composed, steps item by item, and keeps the hero twice apart', async ({ page }) => {
  test.setTimeout(120_000);
  await openLab(page, `./?lecture=${code(LECTURE)}`);
  await expect(page).toHaveTitle('Glass, both ways: Fresnel Lab');
  await expect(page.locator('.site-title h1')).toHaveText('Glass, both ways');
  expect(await page.locator('main > section').evaluateAll((s) => s.map((e) => e.id))).toEqual(KEYS);
  expect(await page.locator('main > .notice').count(), 'a whole lecture names no problem').toBe(0);
  await expect(page.locator('.compose-offer a')).toHaveAttribute('href', /^\.\/compose\.html\?lecture=L1\./);

  // Items as composed: each panel from its state, the lecturer's words with it, text and question items.
  expect(await values(page, 'spheres')).toMatchObject({ nI: 1, nT: 1.7 });
  expect(await values(page, 'spheres--2')).toMatchObject({ nI: 1.5, nT: 1 });
  expect(await values(page, 'r0-derivation')).toMatchObject({ nT: 2.4 });
  const first = page.locator('#spheres');
  await expect(first.locator('.lecture-own-heading')).toHaveText('Into the glass');
  await expect(first.locator('.lecture-text em')).toHaveText('rim');
  await expect(first.locator('.lecture-text .katex').first()).toBeVisible();
  await expect(first.locator('h2').nth(1)).toHaveText("Exact Fresnel vs Schlick's approximation"); // the manifest's section
  await expect(page.locator('#text--2 h2')).toHaveText('Agenda');
  await expect(page.locator('#text--2 ol > li')).toHaveText(['Into the glass', 'Out of it']);
  await expect(page.locator('#question--4 .hw-prompt')).toContainText('predict the angle');
  await expect(page.locator('#polarization .lecture-text')).toHaveText('Where does R_p vanish?');
  // A panel's later item keeps the place the build keeps for the panel (its entry's, two columns at 1280 px), before it mounts.
  expect(await page.evaluate(() => window.fresnelLab.hosts['spheres--2'].mounted)).toBe(false);
  await expect(page.locator('#spheres--2 > .panel-mount')).toHaveCSS('min-height', `${panelEntry('spheres').place.wide}px`);

  // Lecture mode: the clicker keys step over every item, text and question too.
  await page.locator('.site-title h1').click();
  const expectAt = (key) => expect(page).toHaveURL(new RegExp(`#${key}$`));
  for (const [key, press] of [[KEYS[1], 'PageDown'], [KEYS[2], ' '], [KEYS[3], 'PageDown'], [KEYS[4], 'PageDown'], [KEYS[3], 'PageUp']]) {
    await page.keyboard.press(press);
    await expectAt(key);
  }
  await page.keyboard.press('h');
  await expect(page.locator('.panel-side').first()).toBeHidden();
  await page.keyboard.press('h');
  await page.keyboard.press('f');
  await expect.poll(() => page.evaluate(() => document.fullscreenElement !== null)).toBe(true);
  await page.keyboard.press('f');
  await expect.poll(() => page.evaluate(() => document.fullscreenElement === null)).toBe(true);
  // The question: predict, then the lecturer reveals the truth and its panel.
  const question = page.locator('#question--4');
  await expect(question.locator('iframe')).toHaveCount(0);
  await question.getByRole('button', { name: 'Reveal the answer' }).click();
  await expect(question.locator('.hw-result')).toContainText('The computed answer is');
  await expect(question.locator('iframe')).toHaveCount(1);

  // The second hero: its lock holds, a change to it leaves the first alone, and the URL keeps them apart.
  await page.keyboard.press('PageUp');
  await expectAt('spheres--2');
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts['spheres--2'].mounted)).toBe(true);
  await expect(page.locator('#spheres--2 .lil-gui .lil-controller', { hasText: 'n_i (incident side)' })).toHaveClass(/disabled/);
  await nT(page, 'spheres--2').fill('1.2');
  await nT(page, 'spheres--2').press('Enter');
  await expect(page).toHaveURL(/[?&]spheres--2\.nT=1\.2(&|#|$)/);
  expect(await values(page, 'spheres')).toMatchObject({ nI: 1, nT: 1.7 });
  expect(page.url()).not.toMatch(/[?&]nT=/); // the first hero is at its start: nothing of it in the link
  const links = await page.evaluate(() => window.fresnelLab.hosts['spheres--2'].links());
  const lectureLink = new URL(links.lecture);
  expect(lectureLink.searchParams.get('lecture')).toMatch(/^L1\./);
  expect(lectureLink.searchParams.get('spheres--2.nT')).toBe('1.2');
  expect(lectureLink.hash).toBe('#spheres--2');
  const embed = new URL(links.embed);
  expect(Object.fromEntries(embed.searchParams)).toMatchObject({ panel: 'spheres', nI: '1.5', nT: '1.2', lock: 'nI' });
  expect(await seriousViolations(page), 'the composed lecture, the hero twice on it').toEqual([]);

  // The item's link opens the same lecture with both heroes as they were.
  await page.goto('about:blank');
  await openLab(page, links.lecture);
  expect(await values(page, 'spheres')).toMatchObject({ nI: 1, nT: 1.7 });
  expect(await values(page, 'spheres--2')).toMatchObject({ nI: 1.5, nT: 1.2 });
  await expect.poll(() => page.locator('#spheres--2').evaluate((s) => Math.abs(s.getBoundingClientRect().top))).toBeLessThan(40);

  // The page's own settings reach every item: projector mode, and one material for every panel.
  await page.locator('.page-controls input[type="checkbox"]').check();
  await expect(page.locator('html')).toHaveClass(/projector/);
  await page.locator('.page-controls').getByLabel('Material in every panel').selectOption('water');
  await expect.poll(async () => (await values(page, 'spheres')).nT).toBeCloseTo(1.3333, 4);
  for (const key of ['spheres--2', 'r0-derivation']) expect((await values(page, key)).nT, key).toBeCloseTo(1.3333, 4);
});

test('a damaged lecture names what it refuses and opens the rest; an unreadable one falls back to the lab’s own', async ({ page }) => {
  const damaged = {
    ...LECTURE,
    items: [
      { type: 'panel', panel: 'schlick', state: { nT: 'abc' } },
      { type: 'panel', panel: 'no-such-panel' },
      { type: 'question', question: 'no-such-question' },
      { type: 'text', text: 'Still here.' },
      { type: 'panel', panel: 'exact-fresnel' },
    ],
  };
  await openLab(page, `./?lecture=${code(damaged)}`);
  const notice = page.locator('main > .notice');
  await expect(notice).toContainText('no-such-panel is no panel');
  await expect(notice).toContainText('no-such-question is no question');
  await expect(notice).toContainText('nT=abc is not a number');
  // Keys are places in the lecture as it opens: what was left out takes none.
  expect(await page.locator('main > section').evaluateAll((s) => s.map((e) => e.id))).toEqual(['schlick', 'text--2', 'exact-fresnel']);
  await expect(page.locator('#text--2')).toContainText('Still here.');

  await page.goto('about:blank');
  await openLab(page, './?lecture=L1.not-a-lecture');
  await expect(page.locator('main > .notice-error')).toContainText('This lecture link cannot be opened');
  await expect(page.locator('main > .notice-error')).toContainText('damaged');
  await expect(page.locator('.site-title h1')).toHaveText('Fresnel Lab');
  expect(await page.locator('main > section[data-panel]').count()).toBeGreaterThan(10); // the lab's own lecture
});

test.describe('a lecture in the page', () => {
  // The page is served through a route here, which the browser counts as another address space: the dev
  // server's live-reload socket is refused, and says so. Nothing else may log an error.
  test.use({ allowedErrors: /WebSocket connection to 'ws:|\[vite\] failed to connect to websocket/ });
  test('a lecture written into the page opens as one from a link, its panels linking to the page', async ({ page }) => {
    const carried = {
      ...LECTURE,
      title: 'Carried </script><b>offline</b>',
      items: [
        { type: 'text', heading: 'Notes', text: 'A <b>tag</b> stays text.' },
        { type: 'panel', panel: 'schlick', state: { nT: 1.33 } },
      ],
    };
    // As the offline export writes it: every < as \u003c, so the element cannot be closed early.
    const element = `<script type="application/json" id="fresnel-lab-lecture">${JSON.stringify(carried).replace(/</g, '\\u003c')}</script>`;
    await page.route(/\/(index\.html)?(\?.*)?$/, async (route) => {
      const response = await route.fetch();
      const html = (await response.text()).replace('</body>', `${element}\n</body>`);
      await route.fulfill({ response, body: html });
    });
    await openLab(page, './');
    expect(await page.evaluate(() => window.fresnelLab.lecture.source)).toBe('data');
    await expect(page.locator('.site-title h1')).toHaveText('Carried </script><b>offline</b>');
    await expect(page.locator('#text--1 .lecture-text')).toHaveText('A <b>tag</b> stays text.');
    expect(await page.locator('.site-title b, .lecture-text b').count(), 'markup in the lecture became elements').toBe(0);
    expect(await values(page, 'schlick')).toMatchObject({ nT: 1.33 });
    const link = new URL(await page.evaluate(() => window.fresnelLab.hosts.schlick.links().lecture));
    expect(link.searchParams.has('lecture'), 'the page holds the lecture: its link needs no code').toBe(false);
    expect(link.pathname).toBe(new URL(page.url()).pathname);
    expect(link.hash).toBe('#schlick');
  });
});
