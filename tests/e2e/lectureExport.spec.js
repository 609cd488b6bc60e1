// A composed lecture carried off the site: the offline single-file lecture (the built
// dist/offline/index.html with the lecture as its data element) and the reveal.js deck, both written
// by the export functions into a folder with a copy of dist/offline, and opened from disk. The
// offline lecture shows the composed items with their states and the lecturer's words, markup in
// them as text; the deck is stepped through in the real reveal.js with the keys a lecturer presses,
// its panels start from their items' states, a panel left gets 'slide:stop', a key handed back by
// a panel moves the deck, and no more than two WebGL contexts are live at any moment. The lecture
// file and the deck opened apart from their folders say in the lab's words where a panel could not load.
// Needs the built site (npm run build). The export modules are loaded through vite (ssrLoadModule),
// since they import reveal.js and the schemas as vite does.
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { unzipSync } from 'fflate';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { createServer } from 'vite';
import { test, expect, labReady } from './fixtures.js';
import { XSS } from './doorFuzz.js';

const root = resolve(import.meta.dirname, '../..');
const lecture = {
  kind: 'fresnel-lab-lecture', version: 1, title: `Glass, twice ${XSS[0]}`,
  items: [
    { type: 'text', heading: 'Agenda', text: `1. Into the glass\n2. Out of it\n\nHead-on $R_0 = 0.04$. ${XSS[1]} [x](${XSS[2]})` },
    { type: 'panel', panel: 'schlick', state: { nT: 1.7 }, heading: `Schlick ${XSS[3]}`, text: 'Where does it part from the exact?' },
    { type: 'panel', panel: 'spheres', state: { nT: 1.9 }, heading: 'Into the glass' },
    { type: 'panel', panel: 'spheres', state: { nI: 1.5, nT: 1 }, lock: ['nI'], heading: 'Out of the glass' },
    { type: 'panel', panel: 'metals', state: { metal: 'copper' } },
    { type: 'question', question: 'critical-predict', seed: 'room 7', text: 'Hands up first.' },
  ],
};

let dir;
let answer; // the question's computed answer for its seed, as the lecture page and the deck must both say it
test.beforeAll(async () => {
  const server = await createServer({
    root, configFile: resolve(root, 'vite.config.js'), logLevel: 'warn', appType: 'custom',
    server: { middlewareMode: true, hmr: false, ws: false }, optimizeDeps: { noDiscovery: true, include: [] },
  });
  try {
    const { lectureDeckHtml } = await server.ssrLoadModule('/src/lecture/deckExport.js');
    const { offlineLectureHtml, offlineLectureZip } = await server.ssrLoadModule('/src/lecture/offlineExport.js');
    const { questionById } = await server.ssrLoadModule('/src/homework/questions.js');
    const { expectedValue, questionParams } = await server.ssrLoadModule('/src/homework/gradeAnswer.js');
    const { formatValue } = await server.ssrLoadModule('/src/homework/formatAnswer.js');
    const question = questionById('critical-predict');
    answer = formatValue(question, expectedValue(question, questionParams(question, 'room 7')));
    dir = mkdtempSync(join(tmpdir(), 'fresnel-lab-export-'));
    // A copy: another build may rewrite dist/ while this runs. The lecture goes beside the embed
    // page (its question's panel is a frame of ./embed.html); the deck goes beside the folder.
    cpSync(resolve(root, 'dist/offline'), join(dir, 'offline'), { recursive: true });
    const page = readFileSync(join(dir, 'offline/index.html'), 'utf8');
    writeFileSync(join(dir, 'offline/my-lecture.html'), offlineLectureHtml(page, lecture));
    writeFileSync(join(dir, 'my-deck.html'), lectureDeckHtml(lecture, { embedUrl: 'offline/embed.html' }));
    // The composer's one download, unpacked as a lecturer would; and the lecture file alone, apart from its folder.
    const pages = Object.fromEntries(['index', 'embed', 'favicon'].map((name) => [name,
      readFileSync(join(dir, `offline/${name}.${name === 'favicon' ? 'svg' : 'html'}`), 'utf8')]));
    const zip = unzipSync(await offlineLectureZip(pages, lecture, 'glass-twice'));
    for (const [path, bytes] of Object.entries(zip).filter(([name]) => !name.endsWith('/'))) {
      mkdirSync(join(dir, 'unzipped', path, '..'), { recursive: true });
      writeFileSync(join(dir, 'unzipped', path), bytes);
    }
    mkdirSync(join(dir, 'alone'));
    writeFileSync(join(dir, 'alone/lecture.html'), offlineLectureHtml(page, lecture));
    writeFileSync(join(dir, 'alone/my-deck.html'), lectureDeckHtml(lecture, { embedUrl: 'offline/embed.html' })); // no offline/ beside it
  } finally {
    await server.close();
  }
});
test.afterAll(() => { if (dir) rmSync(dir, { recursive: true, force: true }); });

const fileUrl = (path) => pathToFileURL(join(dir, path)).href;

test('the offline lecture opened from disk shows the composed lecture, its markup as text', async ({ page }) => {
  test.setTimeout(60_000);
  await page.goto(fileUrl('unzipped/glass-twice/index.html')); // the composer's .zip, unpacked
  await labReady(page);
  expect(await page.evaluate(() => window.fresnelLab.lecture.source)).toBe('data');
  await expect(page.locator('.site-title h1')).toHaveText(lecture.title);
  expect(await page.title()).toBe(`${lecture.title}: Fresnel Lab`);
  const items = page.locator('main section[data-item]');
  await expect(items).toHaveCount(lecture.items.length);
  expect(await items.evaluateAll((all) => all.map((s) => s.dataset.item)))
    .toEqual(['text--1', 'schlick', 'spheres', 'spheres--2', 'metals', 'question--6']);
  await expect(items.nth(0).locator('.lecture-own-heading')).toHaveText('Agenda');
  await expect(items.nth(0).locator('.lecture-text ol li')).toHaveCount(2);
  await expect(items.nth(1).locator('.lecture-own-heading')).toHaveText(lecture.items[1].heading);
  // Each panel from its item's state; the same panel twice keeps its two states apart.
  const values = (key) => page.evaluate((k) => ({ ...window.fresnelLab.hosts[k].values }), key);
  expect(await values('schlick')).toMatchObject({ nT: 1.7 });
  expect(await values('spheres')).toMatchObject({ nI: 1, nT: 1.9 });
  expect(await values('spheres--2')).toMatchObject({ nI: 1.5, nT: 1 });
  expect(await values('metals')).toMatchObject({ metal: 'copper' });
  await expect(items.nth(5)).toContainText('Hands up first.');
  // Revealed, the question says the deck's answer, and its panel is a frame of the embed page beside the file.
  await items.nth(5).getByRole('button', { name: 'Reveal the answer' }).click();
  await expect(items.nth(5)).toContainText(`The computed answer is ${answer}`);
  await expect(items.nth(5).locator('iframe')).toHaveAttribute('src', /^file:.*\/glass-twice\/embed\.html\?.*panel=refraction-waves/);
  await expect(page.frameLocator('section[data-item="question--6"] iframe').locator('.embed-title')).toBeVisible({ timeout: 30_000 });
  expect(await page.evaluate(() => window.__xss)).toBeUndefined();
  expect(await page.locator('main img, main svg[onload], main a[href^="javascript"]').count()).toBe(0);
});

test.describe('the lecture file alone, apart from its folder', () => {
  // The frame of the missing embed.html is the browser's own error page, which it logs.
  test.use({ allowedErrors: /ERR_FILE_NOT_FOUND|Failed to load resource|Not allowed to load local resource/ });
  test('says in the lab\'s words that a question\'s panel cannot load, and shows no error page', async ({ page }) => {
    test.setTimeout(60_000);
    await page.goto(fileUrl('alone/lecture.html'));
    await labReady(page);
    const question = page.locator('section[data-item="question--6"]');
    await question.getByRole('button', { name: 'Reveal the answer' }).click();
    await expect(question.locator('.notice')).toContainText('The panel could not be shown here.', { timeout: 30_000 });
    await expect(question.locator('.notice')).toContainText('embed.html');
    await expect(question.locator('iframe')).toHaveCount(0);
  });
});

test.describe('the deck alone, without the offline folder beside it', () => {
  test.use({ allowedErrors: /ERR_FILE_NOT_FOUND|Failed to load resource|Not allowed to load local resource/ });
  test('says in each panel\'s place, in the lab\'s words, that its page did not load', async ({ page }) => {
    test.setTimeout(60_000);
    await page.goto(`${fileUrl('alone/my-deck.html')}#/2`); // Schlick, preloaded with its neighbours
    await page.waitForFunction(() => window.deck?.isReady());
    const slide = page.locator('.reveal .slides > section[data-item="2"]');
    const notice = slide.locator('.fl-missing[role="alert"]');
    await expect(notice).toContainText('The panel could not be shown here.', { timeout: 30_000 });
    await expect(notice).toContainText('Its page, offline/embed.html, did not load');
    await expect(slide.locator('iframe')).toHaveCount(0);
    await expect(slide.locator('h2')).toHaveText(lecture.items[1].heading); // the slide's own words stay
    // A WebGL panel's frame, loaded when its slide is shown, likewise.
    await page.keyboard.press('ArrowRight');
    const hero = page.locator('.reveal .slides > section[data-item="3"]');
    await expect(hero.locator('.fl-missing')).toContainText('The panel could not be shown here.', { timeout: 30_000 });
    await expect(hero.locator('iframe')).toHaveCount(0);
  });
});

/** Live WebGL contexts summed over the deck's frames (each embed counts its own). */
async function liveContexts(page) {
  let live = 0;
  for (const frame of page.frames().filter((f) => f.url().includes('embed.html'))) {
    live += await frame.evaluate(() => window.fresnelLab?.contexts.live ?? 0).catch(() => 0);
  }
  return live;
}
const frameOf = (page, id) => page.frames().find((f) => f.url().includes(`panel=${id}`)) ?? null;
const hostOf = (page, id, read) => frameOf(page, id)?.evaluate(read, id).catch(() => null) ?? null;
const mounted = (page, id) => hostOf(page, id, (pid) => window.fresnelLab?.hosts[pid]?.mounted ?? null);
const drawn = (page, id) => hostOf(page, id, (pid) => window.fresnelLab?.hosts[pid]?.frames ?? 0);
const indices = (page) => page.evaluate(() => window.deck.getIndices());

test('the deck from disk, stepped through in reveal.js: states, slide:stop, clicker keys, at most two WebGL contexts', async ({ page }) => {
  test.setTimeout(90_000);
  await page.goto(fileUrl('my-deck.html'));
  await page.waitForFunction(() => window.deck?.isReady());
  expect(await page.title()).toBe(lecture.title);
  const current = page.locator('.reveal .slides section.present:not(.stack)'); // the slide shown, in a stack the one shown
  await expect(page.locator('.reveal .slides > section[data-item]')).toHaveCount(lecture.items.length);
  // Sampled all along: the sum over the frames of their live contexts.
  const peak = { live: 0, samples: 0 };
  let sampling = true;
  const sampler = (async () => {
    while (sampling) {
      peak.live = Math.max(peak.live, await liveContexts(page));
      peak.samples += 1;
      await new Promise((r) => { setTimeout(r, 40); }); // the sampling interval, not a wait for a state
    }
  })();
  try {
    await page.keyboard.press('ArrowRight'); // the agenda
    await expect.poll(() => indices(page)).toEqual({ h: 1, v: 0, f: undefined });
    await expect(current.locator('h2')).toHaveText('Agenda');
    await expect(current.locator('.lecture-math math')).toHaveCount(1);
    // The math as the site draws it: KaTeX's HTML with its own CSS and fonts from inside the file (its MathML, for
    // screen readers, hidden by that CSS), not the browser's MathML, which needs a math font the machine may lack.
    await expect(current.locator('.lecture-math .katex-html')).toBeVisible();
    expect(await current.locator('.lecture-math .katex-mathml').evaluate((e) => getComputedStyle(e).position)).toBe('absolute');
    await expect.poll(() => page.evaluate(async () => { await document.fonts.ready; return document.fonts.check('20px KaTeX_Main'); }))
      .toBe(true);

    await page.keyboard.press('Space'); // Schlick, preloaded: drawn from its item's state
    await expect.poll(() => mounted(page, 'schlick')).toBe(true);
    // Whole on its slide: no scrolling inside the frame (fit=1 scales the panel down as far as it must).
    const overflow = (id) => hostOf(page, id, () => document.documentElement.scrollHeight - window.innerHeight);
    await expect.poll(() => overflow('schlick')).toBeLessThanOrEqual(2);
    expect(await hostOf(page, 'schlick', (pid) => window.fresnelLab.hosts[pid].values.nT)).toBe(1.7);
    await expect(current.locator('h2')).toHaveText(lecture.items[1].heading);
    await frameOf(page, 'schlick').evaluate(() => {
      window.__heard = [];
      window.addEventListener('message', (event) => window.__heard.push(event.data));
    });

    await page.keyboard.press('ArrowRight'); // the hero, loaded on its slide; Schlick's slide was left
    await expect.poll(() => mounted(page, 'spheres')).toBe(true);
    await expect.poll(() => drawn(page, 'spheres')).toBeGreaterThan(0);
    await expect.poll(() => overflow('spheres')).toBeLessThanOrEqual(2);
    expect(await hostOf(page, 'spheres', (pid) => window.fresnelLab.hosts[pid].values.nT)).toBe(1.9);
    await expect.poll(() => hostOf(page, 'schlick', () => window.__heard)).toContain('slide:stop');
    await expect.poll(() => mounted(page, 'schlick')).toBe(false);

    await page.keyboard.press('ArrowRight'); // the hero again, from the second item's state; the first frame is unloaded
    await expect.poll(() => hostOf(page, 'spheres', (pid) => window.fresnelLab?.hosts[pid]?.values.nI ?? null)).toBe(1.5);
    expect(await hostOf(page, 'spheres', (pid) => window.fresnelLab.hosts[pid].values.nT)).toBe(1);
    await expect.poll(() => mounted(page, 'spheres')).toBe(true);
    await expect.poll(() => page.frames().filter((f) => f.url().includes('panel=spheres')).length).toBe(1);

    await page.keyboard.press('Space'); // metals
    await expect.poll(() => mounted(page, 'metals')).toBe(true);
    expect(await hostOf(page, 'metals', (pid) => window.fresnelLab.hosts[pid].values.metal)).toBe('copper');
    await expect.poll(() => frameOf(page, 'spheres')).toBeNull();

    await page.keyboard.press('ArrowRight'); // the question, no panel until its answer
    await expect.poll(() => indices(page)).toEqual({ h: 6, v: 0, f: undefined });
    await expect(current.locator('.fl-prompt')).toContainText('Predict the angle of incidence');
    await expect(current).toContainText('Hands up first.');
    await expect.poll(() => frameOf(page, 'metals')).toBeNull();

    await page.keyboard.press('Space'); // its answer, with the question's panel
    await expect.poll(() => indices(page)).toEqual({ h: 6, v: 1, f: undefined });
    await expect(current.locator('.fl-prompt')).toContainText(`The computed answer is ${answer}`);
    await expect.poll(() => mounted(page, 'refraction-waves')).toBe(true);

    // A clicker's key pressed inside the panel comes back to the deck and moves it.
    await page.frameLocator('iframe[src*="panel=refraction-waves"]').locator('.embed-title').click();
    await page.keyboard.press('PageUp');
    await expect.poll(() => indices(page)).toEqual({ h: 6, v: 0, f: undefined });

    // Opened again on a WebGL slide between two others (reveal.js keeps the place in the link):
    // only that slide's panel loads.
    await page.goto('about:blank');
    await page.goto(`${fileUrl('my-deck.html')}#/4`);
    await page.waitForFunction(() => window.deck?.isReady());
    await expect.poll(() => hostOf(page, 'spheres', (pid) => window.fresnelLab?.hosts[pid]?.frames ?? 0)).toBeGreaterThan(0);
    expect(await hostOf(page, 'spheres', (pid) => window.fresnelLab.hosts[pid].values.nI)).toBe(1.5);
    expect(page.frames().filter((f) => f.url().includes('embed.html'))).toHaveLength(1); // metals and the first hero wait for their slides
  } finally {
    sampling = false;
    await sampler;
  }
  expect(peak.samples).toBeGreaterThan(10);
  expect(peak.live).toBeGreaterThanOrEqual(1); // the counter saw the panels' contexts
  expect(peak.live).toBeLessThanOrEqual(2);
  expect(await page.evaluate(() => window.__xss)).toBeUndefined();
  expect(await page.locator('.reveal img, .reveal a[href^="javascript"]').count()).toBe(0);
});
