// The single-file pages (dist/offline, written by npm run build): the lecture opened from disk with
// every panel, the embed opened from disk, and the embed in a sandboxed iframe (an opaque origin,
// which fetches nothing in CORS mode without the server's consent).
import { pathToFileURL } from 'node:url';
import { resolve } from 'node:path';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { test as plain } from '@playwright/test';
import { test, expect, labReady } from './fixtures.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';

// What a page opened from disk asks the network for: a cold page of its own per test.
test.use({ ownPage: true });

const offline = (file) => pathToFileURL(resolve(import.meta.dirname, '../../dist/offline', file)).href;
const built = (file) => pathToFileURL(resolve(import.meta.dirname, '../../dist', file)).href;

/** Every URL the page asks for, to show that nothing comes from outside the file. */
function requests(page) {
  const urls = [];
  page.on('request', (request) => urls.push(request.url()));
  return urls;
}
const fromOutside = (urls) => urls.filter((u) => !/^(file|data|blob):/.test(u));

plain('the lecturer\'s guide gives the single-file lecture\'s size as built, within a tenth', () => {
  const guide = readFileSync(resolve(import.meta.dirname, '../../docs/lecturer/offline.md'), 'utf8');
  const [, mb, kb] = /`dist\/offline\/index\.html`: [^;]*?about ([\d.]+) MB \((\d+) KB gzipped\)/.exec(guide) ?? [];
  const file = readFileSync(resolve(import.meta.dirname, '../../dist/offline/index.html'));
  expect(Math.abs(Number(mb) * 1e6 / file.length - 1), `docs/lecturer/offline.md: ${mb} MB, built ${file.length} bytes`).toBeLessThan(0.1);
  expect(Math.abs(Number(kb) * 1e3 / gzipSync(file).length - 1), `docs/lecturer/offline.md: ${kb} KB gzipped`).toBeLessThan(0.1);
});

test('the single-file lecture page opened from disk mounts and draws every panel', async ({ page }) => {
  test.setTimeout(120_000);
  const urls = requests(page);
  await page.goto(offline('index.html'));
  await labReady(page);
  for (const id of PANEL_IDS) {
    await page.locator(`section[data-panel="${id}"]`).evaluate((s) => s.scrollIntoView({ block: 'center' }));
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].frames, id), { message: id, timeout: 30_000 })
      .toBeGreaterThan(0);
    await expect(page.locator(`section[data-panel="${id}"] .panel-description`)).toHaveText(/\d/);
  }
  // Formulas typeset with KaTeX's own fonts, and the normal-map chains built off the page's thread.
  await expect(page.locator('section[data-panel="schlick"] .katex').first()).toBeVisible();
  expect(await page.evaluate(() => document.fonts.check('20px KaTeX_Main'))).toBe(true);
  await page.locator('section[data-panel="normal-mips"]').evaluate((s) => s.scrollIntoView({ block: 'center' }));
  await expect(page.locator('section[data-panel="normal-mips"] .nm-summary')).toContainText(/built in \d+ ms \(\d worker/);
  expect(fromOutside(urls)).toEqual([]);
});

test('the single-file embed opened from disk shows a panel, with its URL parameters', async ({ page }) => {
  const urls = requests(page);
  for (const [id, query] of [['schlick', '&nT=1.33'], ['spheres', '&nT=2'], ['normal-mips', '']]) {
    await page.goto(`${offline('embed.html')}?panel=${id}${query}`);
    await labReady(page);
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].frames, id), { message: id }).toBeGreaterThan(0);
    if (query) expect(await page.evaluate((pid) => window.fresnelLab.hosts[pid].values.nT, id)).toBe(Number(query.split('=')[1]));
  }
  expect(fromOutside(urls)).toEqual([]);
});

test('the single-file embed works in a sandboxed iframe on a plain static server and answers messages', async ({ page }) => {
  await page.goto('./embed.html?panel=angle-ratio'); // a page of the server, to be the embedding page
  await labReady(page);
  const answers = await page.evaluate(async () => {
    document.body.innerHTML = '';
    const frame = document.createElement('iframe');
    frame.setAttribute('sandbox', 'allow-scripts');
    frame.style.cssText = 'width:900px;height:600px;border:0';
    const seen = [];
    const next = (type) => new Promise((resolve) => {
      const on = (event) => {
        if (event.source !== frame.contentWindow || event.data?.type !== type) return;
        removeEventListener('message', on);
        seen.push(event.origin);
        resolve(event.data);
      };
      addEventListener('message', on);
    });
    const ready = next('fresnel-lab:ready');
    frame.src = 'offline/embed.html?panel=schlick';
    document.body.append(frame);
    await ready;
    await next('fresnel-lab:rendered'); // the first frame, drawn after ready
    const state = next('fresnel-lab:state');
    const rendered = next('fresnel-lab:rendered'); // the plot redrawn with the new index
    frame.contentWindow.postMessage({ type: 'fresnel-lab:set', params: { nT: 1.7 } }, '*');
    return { state: await state, frame: (await rendered).frame, origins: seen };
  });
  expect(answers.state.params.nT).toBe(1.7);
  expect(answers.frame).toBeGreaterThan(1);
  expect(answers.origins).toEqual(['null', 'null', 'null', 'null']); // an opaque origin: the sandbox held
});

test('the single-file homework page opened from disk runs a sheet, its panels in frames of the offline embed', async ({ page }) => {
  test.setTimeout(120_000); // two frames each parse the 1.6 MB embed page
  const urls = requests(page);
  const sheet = { version: 1, title: 'From disk', items: [{ question: 'critical-predict' }, { question: 'r0-value' }] };
  await page.goto(`${offline('homework.html')}?sheet=${Buffer.from(JSON.stringify(sheet)).toString('base64url')}&seed=disk`);
  await page.locator('#question-1').getByRole('slider').press('ArrowRight');
  await page.locator('#question-1').getByRole('button', { name: 'Commit prediction' }).click();
  await expect(page.locator('#question-1 .predict-true')).toHaveCount(1);
  // Each frame grows to fit once its panel is up (the embed's size message, which comes after ready).
  for (const n of [1, 2]) {
    const frame = page.locator(`#question-${n} iframe`);
    await frame.scrollIntoViewIfNeeded();
    await expect(frame).toHaveAttribute('src', /^file:.*\/offline\/embed\.html\?.*panel=/);
    await expect.poll(() => frame.evaluate((f) => f.style.height), { message: `frame ${n}`, timeout: 60_000 }).toMatch(/^\d+px$/);
  }
  await expect(page.frameLocator('#question-2 iframe').locator('.embed-title')).toHaveText(/R\(0°\)/, { timeout: 60_000 });
  expect(fromOutside(urls)).toEqual([]);
});

// Without the fixture: the browser logs its refusals of the module scripts as errors, which is the point.
plain('the ordinary build opened from disk says which page to open instead', async ({ page }) => {
  await page.goto(built('index.html'));
  await expect(page.locator('.needs-server')).toBeVisible();
  await expect(page.locator('.needs-server')).toContainText('offline/index.html');
  await page.goto(`${built('embed.html')}?panel=schlick`);
  await expect(page.locator('.needs-server')).toContainText('offline/embed.html');
  await page.goto(built('homework.html'));
  await expect(page.locator('.needs-server')).toContainText('offline/homework.html');
  // Served, and in the single-file pages, the line never shows.
  await page.goto(offline('index.html'));
  await labReady(page);
  await expect(page.locator('.needs-server')).toBeHidden();
});
