// Download only what is used, draw only on screen: which modules a page fetches, and what it
// announces. three.js is recognised by its WebGLRenderer in a script's text.
import { test, expect, openDeck, openLab, labReady } from './fixtures.js';
import { mountedHeight, reservedHeight } from './layout.js';
import { pathToFileURL } from 'node:url';
import { resolve } from 'node:path';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { createHash } from 'node:crypto';
import { INJECTION_ERRORS, expectInjectionRefused, policyMeta, recordViolations, violations } from './policyCheck.js';
import { PANELS, PANEL_IDS } from '../../src/panels/manifest.js';

// What a first visit fetches: a cold page of its own per test, no warm cache.
test.use({ ownPage: true });

/** Every script the page fetches; `all()` resolves to them once each one's text has been read. */
function watchScripts(page) {
  const seen = [];
  page.on('response', (response) => {
    if (response.request().resourceType() !== 'script') return;
    seen.push(response.text().catch(() => '').then((body) => ({
      url: response.url(), three: body.includes('WebGLRenderer'), katex: body.includes('KaTeX'),
    })));
  });
  return { all: () => Promise.all(seen) };
}

test('a plot-only embed and the hero load no three.js; KaTeX comes only with formulas', async ({ page }) => {
  const plotOnly = watchScripts(page);
  await openLab(page, './embed.html?panel=schlick');
  await expect(page.locator('.katex').first()).toBeVisible(); // the formulas are typeset after the plot
  const scripts = await plotOnly.all();
  expect(scripts.some((s) => s.three), scripts.map((s) => s.url).join('\n')).toBe(false);
  expect(scripts.some((s) => s.katex)).toBe(true);

  const heroPage = await page.context().newPage(); // a page of its own: no late response of the first counts
  const hero = watchScripts(heroPage);
  await openLab(heroPage, './embed.html?panel=spheres');
  await expect.poll(() => heroPage.evaluate(() => window.fresnelLab.hosts.spheres.frames)).toBeGreaterThan(0);
  const heroScripts = await hero.all();
  expect(heroScripts.some((s) => s.three)).toBe(false);
  expect(heroScripts.some((s) => s.katex)).toBe(false);
  await heroPage.close();
});

test('the lecture page fetches other panels\' modules only after the first picture is up, and no panel brings three.js', async ({ page }) => {
  const lecture = watchScripts(page);
  await openLab(page, './');
  // Every host exists at once: its values work before its module arrives.
  expect(await page.evaluate(() => window.fresnelLab.hosts.stability.values.method)).toBe('exact-cg');
  // The rest arrive while the page is idle, without scrolling, and none was asked for before the hero drew.
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts.stability.loaded), { timeout: 60_000 }).toBe(true);
  const times = await page.evaluate(() => ({
    firstFrame: performance.getEntriesByName('fresnel-lab:first-frame:spheres')[0].startTime,
    modules: performance.getEntriesByType('resource')
      .filter((e) => /\/assets\/(normal-mips|asphalt|stability)-[^/]*\.js$/.test(e.name)).map((e) => e.startTime),
  }));
  expect(times.modules).toHaveLength(3);
  for (const start of times.modules) expect(start).toBeGreaterThan(times.firstFrame);
  await page.locator('section[data-panel="stability"]').scrollIntoViewIfNeeded();
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts.stability.mounted)).toBe(true);
  // Every panel's module is in by now (ready waits for them); three.js is the benchmark's peer only.
  const scripts = await lecture.all();
  expect(scripts.filter((s) => s.three).map((s) => s.url)).toEqual([]);
});

test('a panel without WebGL announces rendered after a change, like the WebGL ones', async ({ page, baseURL }) => {
  await openDeck(page);
  const frames = await page.evaluate(async (src) => {
    const rendered = [];
    const frame = document.createElement('iframe');
    const next = (type) => new Promise((resolve) => {
      const on = (e) => {
        if (e.source !== frame.contentWindow || e.data?.type !== type) return;
        window.removeEventListener('message', on);
        resolve(e.data);
      };
      window.addEventListener('message', on);
    });
    const ready = next('fresnel-lab:ready');
    frame.src = src;
    document.body.append(frame);
    await ready;
    rendered.push((await next('fresnel-lab:rendered')).frame); // the first picture
    const after = next('fresnel-lab:rendered');
    frame.contentWindow.postMessage({ type: 'fresnel-lab:set', params: { nT: 1.7 } }, '*');
    rendered.push((await after).frame);
    return rendered;
  }, `${baseURL}embed.html?panel=schlick`);
  expect(frames[1]).toBeGreaterThan(frames[0]);
});

test('each panel\'s place is reserved before it mounts, and never taller than the panel (at 1280 px: a11y.spec.js)', async ({ page }) => {
  test.setTimeout(180_000);
  for (const width of [800, 1920]) {
    await page.setViewportSize({ width, height: 800 });
    await openLab(page, './');
    const ids = await page.evaluate(() => Object.keys(window.fresnelLab.hosts));
    for (const id of ids) {
      const reserved = await reservedHeight(page, id);
      await page.evaluate((pid) => document.getElementById(pid).scrollIntoView(), id);
      await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].mounted, id), { timeout: 60_000 }).toBe(true);
      const height = await mountedHeight(page, id);
      expect(reserved, `${id} at ${width} px`).toBeLessThanOrEqual(height);
      expect(reserved, `${id} at ${width} px`).toBeGreaterThan(0.4 * height);
    }
  }
});

// Served without any CSP header (vite preview sends none) and opened from disk: each built page
// carries its own policy, works under it, and refuses an injected script.
test.describe('the built pages\' Content-Security-Policy meta', () => {
  test.use({ allowedErrors: INJECTION_ERRORS });

  /** Scrolls through the lecture page until every panel has drawn. */
  async function everyPanelDrawn(page) {
    for (const id of PANEL_IDS) {
      await page.locator(`section[data-panel="${id}"]`).evaluate((s) => s.scrollIntoView({ block: 'center' }));
      await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].frames, id), { message: id, timeout: 60_000 })
        .toBeGreaterThan(0);
    }
  }

  test('served pages: every panel, an editor, an export, the homework page and the deck run under it', async ({ page }) => {
    test.setTimeout(180_000);
    await recordViolations(page);
    expect((await page.request.get('./')).headers()['content-security-policy']).toBeUndefined();
    await openLab(page, './');
    expect(await policyMeta(page)).toMatch(/script-src 'self'; style-src 'self';/);
    await everyPanelDrawn(page);
    await expect(page.locator('section[data-panel="shader-lab"] .cm-editor .cm-line').first()).toBeVisible();
    expect(await violations(page)).toEqual([]);
    await expectInjectionRefused(page);

    await openLab(page, './embed.html?panel=angle-ratio'); // its PNG copies styles into an SVG
    await policyMeta(page);
    await expect.poll(() => page.evaluate(() => window.fresnelLab.panels['angle-ratio'].png()?.slice(0, 22))).toBe('data:image/png;base64,');
    const coloured = await page.evaluate(async () => { // the rays keep their colours (styles written through the CSSOM)
      const image = new Image();
      image.src = window.fresnelLab.panels['angle-ratio'].png();
      await image.decode();
      const g = Object.assign(document.createElement('canvas'), { width: image.width, height: image.height }).getContext('2d');
      g.drawImage(image, 0, 0);
      const d = g.getImageData(0, 0, image.width, image.height).data;
      let count = 0;
      for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[i + 1]) + Math.abs(d[i + 1] - d[i + 2]) > 80) count += 1;
      return count;
    });
    expect(coloured).toBeGreaterThan(500);
    await page.goto('./homework.html');
    await policyMeta(page);
    await expect(page.getByRole('button', { name: /SCORM/ })).toBeVisible();
    await page.goto('./examples/deck.html');
    expect(await policyMeta(page)).toMatch(/style-src 'self' 'sha256-/); // its own <style>, by hash
    await page.waitForFunction(() => window.deck?.isReady());
    expect(await violations(page)).toEqual([]);
  });

  test('the single-file lecture page from disk: inline script and style by hash, fonts data:, workers blob:', async ({ page }) => {
    test.setTimeout(180_000);
    await recordViolations(page);
    await page.goto(pathToFileURL(resolve(import.meta.dirname, '../../dist/offline/index.html')).href);
    await labReady(page);
    const policy = await policyMeta(page);
    expect(policy).toMatch(/script-src 'sha256-[\w+/=]+'; style-src 'sha256-[\w+/=]+'; img-src 'self' data:; font-src data:; worker-src blob:/);
    await everyPanelDrawn(page);
    await page.locator('section[data-panel="normal-mips"]').evaluate((s) => s.scrollIntoView({ block: 'center' }));
    await expect(page.locator('section[data-panel="normal-mips"] .nm-summary')).toContainText(/built in \d+ ms \(\d worker/);
    expect(await page.evaluate(() => document.fonts.check('20px KaTeX_Main'))).toBe(true);
    expect(await violations(page)).toEqual([]);
    await expectInjectionRefused(page);
  });
});

const DIST = resolve(import.meta.dirname, '../../dist');
/** The built site's chunk manifest (vite's build.manifest). */
const builtManifest = () => JSON.parse(readFileSync(resolve(DIST, '.vite/manifest.json'), 'utf8'));

/** The chunks a manifest key imports statically, itself included, as dist paths (dist/.vite/manifest.json). */
function staticClosure(manifest, key, seen = new Set()) {
  const entry = manifest[key];
  if (!entry || seen.has(entry.file)) return seen;
  seen.add(entry.file);
  for (const next of entry.imports ?? []) staticClosure(manifest, next, seen);
  return seen;
}

/**
 * KB of gzipped JS in the built `files` (zlib's default level, as a static server sends them). A
 * chunk's hashed name, which changes with any file and sits in the chunks that import it, is read
 * with a hash made from the chunk's name alone, as random as the real one: a bar then moves with
 * the code, not with the hashes (they moved a closure by tens of bytes from one build to the next).
 */
function gzippedKb(files) {
  const stable = (name) => createHash('sha256').update(name).digest('base64url').slice(0, 8);
  const text = (file) => readFileSync(resolve(DIST, file), 'utf8')
    .replace(/([\w.]+)-[\w-]{8}\.(js|css)\b/g, (_, name, ext) => `${name}-${stable(name)}.${ext}`);
  return [...files].reduce((sum, file) => sum + gzipSync(text(file)).length, 0) / 1024;
}

test('before its first picture the lecture page fetches only what that picture needs, at most 96.8 KB of gzipped JS', async ({ page }) => {
  const manifest = builtManifest();
  // Needed: the page's module and what it imports, the hero's module and what it imports, and the
  // worker that compiles the hero's shaders ahead (gl/warmGpu.js). Nothing else may come first:
  // not the Markdown renderer or KaTeX (no lecturer text on the lab's own lecture), not the
  // lecture reader, the questions, the audio of other panels, or another panel's module.
  const needed = new Set([...staticClosure(manifest, 'index.html'), ...staticClosure(manifest, 'src/panels/spheres/index.js')]);
  await openLab(page, './');
  await expect.poll(() => page.evaluate(() => performance.getEntriesByName('fresnel-lab:first-frame:spheres').length)).toBe(1);
  const before = await page.evaluate(() => {
    const first = performance.getEntriesByName('fresnel-lab:first-frame:spheres')[0].startTime;
    return performance.getEntriesByType('resource').filter((r) => r.startTime <= first && /\.js$/.test(new URL(r.name).pathname))
      .map((r) => new URL(r.name).pathname.replace(/^\//, ''));
  });
  const unneeded = before.filter((file) => !needed.has(file) && !/gpuWarmWorker/.test(file));
  expect(unneeded, 'fetched before the first picture, though it does not need them').toEqual([]);
  // And what the lab's own lecture never needs is not imported by the page either, statically or not.
  const lectureOnly = /\/(lectureTextDom|composedLecture|openLecture|mountLecture|questions|katex|typesetTex)-[\w-]+\.js$/;
  expect(before.filter((file) => lectureOnly.test(`/${file}`)), 'the lecture reader, Markdown or KaTeX before the first picture').toEqual([]);
  const kb = gzippedKb(before);
  console.log(`[first load] lecture page: ${kb.toFixed(1)} KB of gzipped JS before the hero's first frame (${before.length} files)`);
  // 96.8 KB before the words moved into the message catalogue: English must not cost more than that.
  expect(kb).toBeLessThanOrEqual(96.8);
});

// What an embed imports before its panel can draw, by the figures of 2026-12-04: a plot
// embed 78 KB of gzipped JS, a WebGL embed 97 KB. Two carry more, held where they are: the
// normal-map viewer (its chain builder and its figures) and the shader lab (CodeMirror's editor).
const EMBED_KB = { plot: 78, webgl: 97, 'normal-mips': 115, 'shader-lab': 199 };

test('each panel\'s embed imports at most its bar of gzipped JS before it can draw', async () => {
  const manifest = builtManifest();
  const over = [];
  for (const { id, webgl, webglAtTimes } of PANELS) {
    const files = new Set([...staticClosure(manifest, 'embed.html'), ...staticClosure(manifest, `src/panels/${id}/index.js`)]);
    const kb = gzippedKb(files);
    const bar = EMBED_KB[id] ?? (webgl || webglAtTimes ? EMBED_KB.webgl : EMBED_KB.plot);
    if (kb > bar) over.push(`${id}: ${kb.toFixed(2)} KB > ${bar}`);
  }
  expect(over).toEqual([]);
});

// What the homework page and the composer import before they can draw, in English: the page's
// module and what it imports, with the part of the page a visit shows first (fetched at once, by
// a dynamic import). Bars at what they came to once each took only what it shows (2026-12-05); before
// the words moved into the message catalogue the homework page imported 69.1 KB and the composer 174.3.
const PAGE_KB = [
  { page: 'a student\'s sheet (homework.html?sheet=…)', keys: ['homework.html', 'src/homework/page/showSheet.js'], bar: 63 },
  { page: 'the lecturer\'s homework page', keys: ['homework.html', 'src/homework/page/lecturerPage.js'], bar: 69 },
  { page: 'the composer', keys: ['compose.html'], bar: 68 },
  // An item's editor comes with the first item; a panel item's start, with the controls' names, with the first panel item.
  { page: 'the composer with a text or a question', keys: ['compose.html', 'src/compose/buildItemEditor.js'], bar: 70 },
  { page: 'the composer with a panel item', keys: ['compose.html', 'src/compose/buildItemEditor.js', 'src/compose/buildPanelStart.js'], bar: 93 },
];

test('the homework page and the composer import at most their bars of gzipped JS before they can draw', async () => {
  const manifest = builtManifest();
  const sizes = [];
  for (const { page, keys, bar } of PAGE_KB) {
    for (const key of keys) expect.soft(manifest[key], `${key} is a chunk of its own`).toBeDefined();
    const kb = gzippedKb(new Set(keys.flatMap((key) => [...staticClosure(manifest, key)])));
    console.log(`[first load] ${page}: ${kb.toFixed(2)} KB of gzipped JS (bar ${bar})`);
    sizes.push({ page, kb, bar });
  }
  expect(sizes.filter(({ kb, bar }) => kb > bar).map(({ page, kb, bar }) => `${page}: ${kb.toFixed(1)} KB > ${bar}`)).toEqual([]);
});
