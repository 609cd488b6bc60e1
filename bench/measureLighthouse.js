// Lighthouse (12.2.3, the last release that runs on Node 20) on the lecture page, desktop preset,
// performance only, in the same Chromium and with the same software-GPU flags as the rest of the
// benchmark. Each run is a fresh browser; the median of `runs` and the spread are reported.
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { spread } from './measurePages.js';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const cli = join(root, 'node_modules', 'lighthouse', 'cli', 'index.js');

function lighthouseOnce(url, { executablePath, args }, out) {
  const flags = ['--headless=new', ...args.filter((a) => !a.startsWith('--headless'))].join(' ');
  return new Promise((done, fail) => {
    const child = spawn(process.execPath, [cli, url, '--preset=desktop', '--only-categories=performance', '--output=json',
      `--output-path=${out}`, `--chrome-flags=${flags}`, '--quiet'], {
      cwd: root, stdio: ['ignore', 'ignore', 'inherit'], env: { ...process.env, ...(executablePath ? { CHROME_PATH: executablePath } : {}) },
    });
    child.on('error', fail);
    child.on('exit', (code) => (code === 0 ? done() : fail(new Error(`lighthouse exited with ${code}`))));
  });
}

/** { runs, score, totalBlockingTimeMs, cumulativeLayoutShift, largestContentfulPaintMs, firstContentfulPaintMs, speedIndexMs } as spreads. */
export async function lighthouse(url, launchOptions, { runs = 3 } = {}) {
  const dir = mkdtempSync(join(tmpdir(), 'fresnel-lab-lighthouse-'));
  const samples = [];
  try {
    for (let i = 0; i < runs; i += 1) {
      const out = join(dir, `run-${i}.json`);
      await lighthouseOnce(url, launchOptions, out);
      const { categories, audits } = JSON.parse(readFileSync(out, 'utf8'));
      const value = (id) => audits[id].numericValue;
      samples.push({
        score: Math.round(categories.performance.score * 100),
        totalBlockingTimeMs: value('total-blocking-time'),
        cumulativeLayoutShift: value('cumulative-layout-shift'),
        largestContentfulPaintMs: value('largest-contentful-paint'),
        firstContentfulPaintMs: value('first-contentful-paint'),
        speedIndexMs: value('speed-index'),
      });
    }
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
  const of = (key) => spread(samples.map((s) => s[key]));
  return {
    runs, preset: 'desktop', version: JSON.parse(readFileSync(join(root, 'node_modules', 'lighthouse', 'package.json'), 'utf8')).version,
    score: of('score'), totalBlockingTimeMs: of('totalBlockingTimeMs'), cumulativeLayoutShift: of('cumulativeLayoutShift'),
    largestContentfulPaintMs: of('largestContentfulPaintMs'), firstContentfulPaintMs: of('firstContentfulPaintMs'), speedIndexMs: of('speedIndexMs'),
  };
}
