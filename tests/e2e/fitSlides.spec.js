// Every panel of the manifest fitted to a slide's frame (embed option fit=1, src/host/fitToFrame.js):
// in a frame of 1216 × 651 (a 1280 × 720 deck slide with a heading) and one of 1216 × 577 (a heading
// and a line of text with math), side by side in one page. Each panel fits both: nothing to scroll,
// every canvas and plot inside the frame, and type no smaller than the floor; or, only where
// docs/deck/embed.md lists it, it scrolls inside its frame and its cue says so. The zoom each panel
// ends at is reported.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { test, expect } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';

const FRAMES = [{ name: 'heading', height: 651 }, { name: 'text', height: 577 }];
const WIDTH = 1216;
const FLOOR = 0.6; // 12 px body type from the 20 px root (docs/deck/embed.md, "On a slide")

/** The panels docs/deck/embed.md says may scroll on a slide: the list under its comment naming this file. */
function documentedScrolling() {
  const text = readFileSync(resolve(import.meta.dirname, '../../docs/deck/embed.md'), 'utf8');
  const start = text.indexOf('<!-- tests/e2e/fitSlides.spec.js');
  const block = text.slice(start).split('\n\n')[0];
  return [...block.matchAll(/^- `([a-z0-9-]+)`/gm)].map((m) => m[1]);
}

const HOST = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Frames</title></head>
<body style="margin:0">${FRAMES.map(({ name, height }) => `<iframe id="${name}" title="${name}"
 style="display:block;border:0;width:${WIDTH}px;height:${height}px"></iframe>`).join('')}</body></html>`;

/**
 * Waits for the panel in `frame` to be mounted and drawn, and its fitted layout to hold still for
 * 30 animation frames (its content and the layout chosen for it settled), then reads it.
 */
async function settledLayout(frame, id) {
  await frame.waitForFunction((pid) => window.fresnelLab?.hosts?.[pid]?.mounted && window.fresnelLab.fit, id, { timeout: 60_000 });
  return frame.evaluate(() => new Promise((resolveLayout) => {
    let last = '';
    let still = 0;
    const tick = () => {
      // The layout fitToFrame chose; without one, what the root's zoom says.
      const zoom = Number(document.getElementById('embed').style.zoom || 1);
      const layout = window.fresnelLab.fit?.layout ?? { zoom, columns: 1, share: null, searches: 0, scrolls: false };
      const now = JSON.stringify([layout.zoom, layout.columns, layout.share, layout.searches, document.documentElement.scrollHeight]);
      still = now === last ? still + 1 : 0;
      last = now;
      if (still < 30) { requestAnimationFrame(tick); return; }
      const doc = document.documentElement;
      const out = [...document.querySelectorAll('canvas, .uplot')]
        .filter((e) => e.getClientRects().length && !e.closest('.uplot canvas'))
        .map((e) => ({ e, r: e.getBoundingClientRect() }))
        .filter(({ r }) => r.width > 2 && r.height > 2)
        .map(({ e, r }) => ({
          what: `${e.tagName.toLowerCase()}.${[...e.classList].join('.')}`,
          below: r.bottom > innerHeight + 1 || r.top < -1,
          beside: r.right > innerWidth + 1 || r.left < -1,
        }))
        .filter((o) => o.below || o.beside);
      const cue = document.querySelector('.fit-cue');
      const cueBox = cue && !cue.hidden ? cue.getBoundingClientRect() : null;
      resolveLayout({
        ...layout,
        over: doc.scrollHeight - doc.clientHeight,
        overSideways: doc.scrollWidth - doc.clientWidth,
        out,
        cue: Boolean(cueBox && cueBox.bottom <= innerHeight && cueBox.height > 0),
      });
    };
    tick();
  }));
}

test('every panel fits a slide\'s frame with legible type, or scrolls with a cue where the docs say it may', async ({ page }, testInfo) => {
  test.setTimeout(360_000);
  const mayScroll = documentedScrolling();
  expect(mayScroll.length, 'the list in docs/deck/embed.md').toBeGreaterThan(0);
  await page.route('**/fit-frames.html', (route) => route.fulfill({ contentType: 'text/html', body: HOST }));
  await page.goto('./fit-frames.html');
  const rows = [];
  const problems = [];
  for (const { id } of PANELS) {
    // Both frames load the panel at once, and are read when each has settled.
    await page.evaluate(([names, pid]) => {
      for (const name of names) document.getElementById(name).src = `embed.html?panel=${pid}&fit=1`;
    }, [FRAMES.map((f) => f.name), id]);
    const row = { id };
    for (const { name, height } of FRAMES) {
      const frame = await (await page.$(`#${name}`)).contentFrame();
      await frame.waitForURL((url) => url.searchParams.get('panel') === id);
      const got = await settledLayout(frame, id);
      row[height] = got;
      const where = `${id} in ${WIDTH}×${height}`;
      if (got.zoom < FLOOR) problems.push(`${where}: zoom ${got.zoom} below the floor ${FLOOR}`);
      if (got.overSideways > 1) problems.push(`${where}: ${got.overSideways} px wider than the frame`);
      const beside = got.out.filter((o) => o.beside).map((o) => o.what);
      if (beside.length) problems.push(`${where}: out of the frame sideways: ${beside.join(', ')}`);
      if (!got.scrolls) {
        if (got.over > 1) problems.push(`${where}: ${got.over} px to scroll`);
        const below = got.out.filter((o) => o.below).map((o) => o.what);
        if (below.length) problems.push(`${where}: below the frame: ${below.join(', ')}`);
      } else {
        if (!mayScroll.includes(id)) problems.push(`${where}: scrolls (${got.over} px), and docs/deck/embed.md does not say it may`);
        if (got.over <= 1) problems.push(`${where}: says it scrolls with nothing to scroll`);
        if (!got.cue) problems.push(`${where}: scrolls ${got.over} px without the cue in view`);
        // Scrolled to the end (again, where the content grew meanwhile), the cue has said what it had to.
        await expect.poll(() => frame.evaluate(() => new Promise((resolveHidden) => {
          window.scrollTo(0, document.documentElement.scrollHeight);
          requestAnimationFrame(() => requestAnimationFrame(() => resolveHidden(document.querySelector('.fit-cue')?.hidden)));
        })), `${where}: the cue at the end`).toBe(true);
      }
    }
    rows.push(row);
  }
  const cell = (m) => `${m.zoom.toFixed(3)} ${m.columns} col${m.share ? ` pic≤${m.share}` : ''}${m.scrolls ? ` scrolls ${m.over}` : ''}`;
  const report = rows.map((r) => `${r.id.padEnd(18)} ${FRAMES.map((f) => cell(r[f.height]).padEnd(32)).join(' ')}`).join('\n');
  console.log(`[fit] panel             ${FRAMES.map((f) => `${WIDTH}×${f.height}`.padEnd(32)).join(' ')}\n${report}`);
  await testInfo.attach('zoom per panel', { body: report, contentType: 'text/plain' });
  expect(problems).toEqual([]);
});
