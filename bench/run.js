#!/usr/bin/env node
// npm run bench [-- --tiny] [-- --out DIR] [-- --pages-only] [-- --site DIR] [-- --no-lighthouse]
// Builds the site with the benchmark's three.js peer page (into a private folder; --site DIR serves
// a site built already, with bench/peer.html in it), serves it with vite preview on a free loopback
// port, and runs in Chromium launched exactly as playwright.config.js launches it (same executable
// and SwiftShader flags):
// 1. the speed-accuracy panel's benchmark (embed.html?panel=speed-accuracy&bench=…): every method's
//    cost and error, and the normal-mips chain build (its bench());
// 2. the pages (measurePages.js): the hero against the three.js peer per message-driven update,
//    every WebGL panel's update at 1280×720, time to the first frame and gzipped JS per page,
//    layout shift over a scroll of the lecture page, and Lighthouse on it (measureLighthouse.js;
//    --no-lighthouse leaves it out); the homework page grading a synthetic class of 500 hand-ins of
//    a 40-question sheet from its zip and from pasted codes (measureClassView.js; 50 × 10 with --tiny).
// Prints the tables and writes results.json and results.png (the chart) to bench/ (or --out);
// --pages-only runs part 2 alone and merges it into the results.json already there.
import { chromium } from '@playwright/test';
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import config, { TEST_ONLY_ARGS } from '../playwright.config.js';
import { heroVsPeer, layoutShift, pageLoad, panelUpdateCosts, problems } from './measurePages.js';
import { pagesTable } from './pagesTable.js';
import { lighthouse } from './measureLighthouse.js';
import { classView } from './measureClassView.js';
import { PANEL_IDS } from '../src/panels/manifest.js';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const flag = (name) => args.includes(`--${name}`);
const option = (name, fallback) => {
  const i = args.findIndex((a) => a === `--${name}` || a.startsWith(`--${name}=`));
  if (i < 0) return fallback;
  return args[i].includes('=') ? args[i].split('=').slice(1).join('=') : args[i + 1];
};
const size = flag('tiny') ? 'tiny' : option('size', 'normal');
const outDir = resolve(option('out', join(root, 'bench')));
const timeoutMs = Number(option('timeout', 600)) * 1000;
const vite = join(root, 'node_modules', 'vite', 'bin', 'vite.js');
const log = (text) => process.stderr.write(`[bench] ${text}\n`);

function run(command, commandArgs, env = {}) {
  return new Promise((done, fail) => {
    const child = spawn(process.execPath, [command, ...commandArgs], {
      cwd: root, stdio: ['ignore', 'ignore', 'inherit'], env: { ...process.env, ...env },
    });
    child.on('error', fail);
    child.on('exit', (code) => (code === 0 ? done() : fail(new Error(`${commandArgs.join(' ')} exited with ${code}`))));
  });
}

function freePort() {
  return new Promise((done, fail) => {
    const server = createServer().listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => done(port));
    });
    server.on('error', fail);
  });
}

async function waitForServer(url, child, ms = 30_000) {
  const end = Date.now() + ms;
  while (Date.now() < end) {
    if (child.exitCode !== null) throw new Error(`vite preview exited with ${child.exitCode}`);
    try {
      if ((await fetch(url)).ok) return;
    } catch {
      // not up yet
    }
    await new Promise((r) => { setTimeout(r, 200); });
  }
  throw new Error(`no server at ${url} after ${ms / 1000} s`);
}

let site = option('site', null);
let privateBuild = null;
let server = null;
let browser = null;
try {
  if (site) {
    site = resolve(site);
    if (!existsSync(join(site, 'bench', 'peer.html'))) throw new Error(`${site} has no bench/peer.html (build it with FRESNEL_LAB_BENCH_PEER=1)`);
  } else {
    privateBuild = mkdtempSync(join(tmpdir(), 'fresnel-lab-bench-'));
    site = privateBuild;
    log(`building the site into ${site}`);
    await run(vite, ['build', '--outDir', site, '--emptyOutDir', '--logLevel', 'warn'], { FRESNEL_LAB_BENCH_PEER: '1' });
  }
  const port = await freePort();
  server = spawn(process.execPath, [vite, 'preview', '--outDir', site, '--host', '127.0.0.1', '--port', String(port), '--strictPort'], {
    cwd: root, stdio: 'ignore',
  });
  const base = `http://127.0.0.1:${port}/`;
  await waitForServer(base, server);

  // The tests' launch, less what only speeds the tests up: the figures stay comparable with earlier runs.
  const { launchOptions } = config.use;
  const args = launchOptions.args.filter((arg) => !TEST_ONLY_ARGS.includes(arg));
  browser = await chromium.launch({ ...launchOptions, args, headless: true });
  const pagesOnly = flag('pages-only');
  let results = pagesOnly ? JSON.parse(readFileSync(join(outDir, 'results.json'), 'utf8')) : null;
  const page = await browser.newPage({ viewport: config.use.viewport });
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.on('pageerror', (e) => problems.push(e.message));
  log(`running the ${size} benchmark in ${browser.version()} (${launchOptions.executablePath ?? 'Playwright Chromium'})`);
  const started = Date.now();
  let table = '';
  let chainLine = '';
  if (!pagesOnly) {
    await page.goto(`${base}embed.html?panel=speed-accuracy&bench=${encodeURIComponent(size)}`);
    await page.evaluate(() => window.fresnelLab.ready);
    let last = '';
    const ticker = setInterval(async () => {
      const text = await page.locator('.sa-status').textContent().catch(() => '');
      if (text && text !== last) log((last = text));
    }, 1000);
    let timer = 0;
    try {
      results = await Promise.race([
        page.evaluate(async () => {
          const panel = window.fresnelLab.panels['speed-accuracy'];
          return (await panel.autorun) ? panel.resultsJson() : null;
        }),
        new Promise((_r, fail) => { timer = setTimeout(() => fail(new Error(`no results after ${timeoutMs / 1000} s`)), timeoutMs); }),
      ]);
    } finally {
      clearInterval(ticker);
      clearTimeout(timer);
    }
    if (!results) throw new Error(`the benchmark did not finish: ${await page.locator('.sa-status').textContent()}`);
    await page.locator('.sa-chart').screenshot({ path: join(outDir, 'results.png') });
    table = await page.evaluate(() => window.fresnelLab.panels['speed-accuracy'].resultsTable());

    // The normal-map viewer: building every technique's chain for a 1024² map (64² with --tiny).
    const chainSize = size === 'tiny' ? 64 : 1024;
    log(`timing the normal-mips chain build at ${chainSize}²`);
    await page.goto(`${base}embed.html?panel=normal-mips&truth=false`);
    await page.evaluate(() => window.fresnelLab.ready);
    results.normalMips = await page.evaluate((n) => window.fresnelLab.panels['normal-mips'].bench({ size: n, repeats: n > 256 ? 5 : 3 }), chainSize);
    const nm = results.normalMips;
    const ms = ({ median, min, max }) => `${median.toFixed(0)} ms [${min.toFixed(0)}, ${max.toFixed(0)}]`;
    chainLine = `normal-mips: all six chains of a ${nm.size}² map in ${ms(nm.wallMs)} (${nm.where}; build alone ${ms(nm.buildMs)}); `
      + `longest main-thread task ${nm.longestTaskMs.toFixed(0)} ms while building, ${nm.panelLongestTaskMs.toFixed(0)} ms while the panel switched to it; `
      + `ground truth ${nm.truth.samples} samples/pixel in ${(nm.truth.ms / 1000).toFixed(1)} s, longest task meanwhile ${nm.truth.longestTaskMs.toFixed(0)} ms`;
  }
  await page.close();

  // The pages: hero against the peer, every WebGL panel, loads and layout shift.
  const tiny = size === 'tiny';
  log('hero embed against the three.js peer (message-driven updates)');
  const hero = await heroVsPeer(browser, base, tiny ? { width: 300, height: 120, rounds: 1, updates: 3, warmup: 1 } : {});
  log(tiny ? 'the hero and one WebGL panel, interleaved' : 'every WebGL panel, in interleaved rounds with the hero');
  // The tiny run (the browser tests') times the hero and one other panel: the path, not the figures.
  const tinyPanels = { width: 320, height: 240, updates: 2, warmup: 1, runs: 1, ids: ['spheres', 'metals'] };
  const panels = await panelUpdateCosts(browser, base, tiny ? tinyPanels : {});
  log('first frames and downloads');
  const loads = { lecture: await pageLoad(browser, base, site, base, { id: 'spheres' }), embeds: {} };
  for (const id of tiny ? ['spheres', 'schlick'] : PANEL_IDS) {
    loads.embeds[id] = await pageLoad(browser, base, site, `${base}embed.html?panel=${id}`, { id });
  }
  log('layout shift over a scroll of the lecture page');
  const shift = tiny ? null : await layoutShift(browser, base);
  const classSize = tiny ? { students: 50, questions: 10, runs: 1, codeRuns: 1 } : { students: 500, questions: 40, runs: 5, codeRuns: 3 };
  log(`grading a class of ${classSize.students} hand-ins of ${classSize.questions} questions on the homework page`);
  const graded = await classView(browser, base, root, classSize);
  log('Lighthouse on the lecture page (desktop, 3 runs)');
  const audit = tiny || flag('no-lighthouse') ? null : await lighthouse(base, { ...launchOptions, args });
  results.pages = { hero, panels, loads, layoutShift: shift, classView: graded, lighthouse: audit };
  table = `${table}\n${pagesTable(results.pages)}`;

  results.config = { ...results.config, script: 'bench/run.js', wallSeconds: (Date.now() - started) / 1000, chromium: browser.version() };
  mkdirSync(outDir, { recursive: true });
  writeFileSync(join(outDir, 'results.json'), `${JSON.stringify(results, null, 2)}\n`);
  process.stdout.write(`${table}\n${chainLine}\n`);
  log(`wrote ${join(outDir, 'results.json')} and results.png in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  if (problems.length) throw new Error(`the page logged errors:\n${problems.join('\n')}`);
} catch (error) {
  log(`failed: ${error.message}`);
  process.exitCode = 1;
} finally {
  await browser?.close();
  server?.kill('SIGTERM');
  if (privateBuild) rmSync(privateBuild, { recursive: true, force: true });
}
