#!/usr/bin/env node
// npm run places [-- <id> …] [-- --widths 800,1000,1280] [-- --site DIR]
// The `place` of each panel's manifest entry (all panels when no id is given), measured as the
// browser tests measure it: the site is built into a private folder (--site DIR serves one built
// already), served with vite preview, and the lecture page opened in headless Chromium launched as
// playwright.config.js launches it, at each window width (by default both edges of each layout and
// the widths the tests use: within a layout a panel's height does not fall steadily with the width).
// At each width every panel asked for is scrolled to, mounted, and its height taken from the top of
// its mount to the bottom of its description (tests/e2e/layout.js). Prints per panel the heights, the
// line to paste into src/panels/manifest.js (placeFromHeights.js), and what the tests would say of
// the place the entry has now.
import { chromium } from '@playwright/test';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build, preview } from 'vite';
import config from '../playwright.config.js';
import { PANELS, PLACE_LAYOUTS } from '../src/panels/manifest.js';
import { mountedHeight } from '../tests/e2e/layout.js';
import { placeFromHeights, placeLine, placeProblems } from './placeFromHeights.js';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.findIndex((a) => a === `--${name}` || a.startsWith(`--${name}=`));
  if (i < 0) return fallback;
  const value = args[i].includes('=') ? args[i].split('=').slice(1).join('=') : args[i + 1];
  args.splice(i, args[i].includes('=') ? 1 : 2);
  return value;
};
const widths = option('widths', '800,1000,1001,1280,1449,1450,1920,2560').split(',').map(Number);
const givenSite = option('site', null);
const ids = args.length ? args : PANELS.map((p) => p.id);
const log = (text) => process.stderr.write(`[places] ${text}\n`);

const unknown = ids.filter((id) => !PANELS.some((p) => p.id === id));
if (unknown.length || widths.some((w) => !(Number.isInteger(w) && w >= 320))) {
  log(unknown.length ? `not in the manifest: ${unknown.join(', ')}` : `widths are whole px from 320: ${widths.join(', ')}`);
  process.exit(2);
}

/** The layout a window of the page is in: the last of PLACE_LAYOUTS whose media query holds. */
const layoutOf = (page) => page.evaluate((layouts) => Object.entries(layouts)
  .filter(([, media]) => !media || matchMedia(media).matches).at(-1)[0], PLACE_LAYOUTS);

let site = givenSite && resolve(givenSite);
let privateBuild = null;
let server = null;
let browser = null;
try {
  if (!site) {
    site = privateBuild = mkdtempSync(join(tmpdir(), 'fresnel-lab-places-'));
    log(`building the site into ${site}`);
    delete process.env.FRESNEL_LAB_SINGLE_FILE;
    await build({ root, logLevel: 'error', build: { outDir: site, emptyOutDir: true } });
  }
  server = await preview({ root, logLevel: 'warn', build: { outDir: site }, preview: { host: '127.0.0.1', port: 4300 } });
  const base = server.resolvedUrls.local[0];
  browser = await chromium.launch({ ...config.use.launchOptions, headless: true });
  /** @type {Record<string, Record<string, number[]>>} id → layout → heights */
  const heights = Object.fromEntries(ids.map((id) => [id, {}]));
  const seen = [];
  for (const width of widths) {
    const page = await browser.newPage({ viewport: { width, height: 800 } });
    page.on('pageerror', (error) => log(`page error at ${width} px: ${error.message}`));
    await page.goto(base);
    await page.waitForFunction(() => Boolean(window.fresnelLab?.ready));
    await page.evaluate(() => window.fresnelLab.ready);
    const layout = await layoutOf(page);
    for (const id of ids) {
      await page.evaluate((pid) => document.getElementById(pid).scrollIntoView(), id);
      await page.waitForFunction((pid) => window.fresnelLab.hosts[pid].mounted, id, { timeout: 120_000 });
      const height = Math.round(await mountedHeight(page, id));
      (heights[id][layout] ??= []).push(height);
      seen.push({ id, width, layout, height });
    }
    await page.close();
    log(`${width} px (${layout}): measured`);
  }
  for (const id of ids) {
    const { place } = PANELS.find((p) => p.id === id);
    const measured = seen.filter((s) => s.id === id).map((s) => `${s.height} at ${s.width} px (${s.layout})`);
    const problems = placeProblems(place, heights[id]);
    console.log(`${id}: mounted ${measured.join(', ')}`);
    console.log(`    ${placeLine(placeFromHeights(heights[id], place))}`);
    console.log(`  the entry has ${placeLine(place).slice('place: '.length, -1)}: ${problems.length ? problems.join('; ') : 'the tests pass it'}`);
  }
} finally {
  await browser?.close();
  await server?.close();
  if (privateBuild) rmSync(privateBuild, { recursive: true, force: true });
}
