// Page-level measurements for npm run bench, each in a fresh browser context (a cold cache):
// - updateCosts: a run of `fresnel-lab:set` messages to an embed in an iframe of a given size, each
//   sent when the `fresnel-lab:rendered` of the one before arrives (the message-driven update a deck
//   sees). `rendered` comes when a frame's commands are issued, before the GPU has run them, and
//   the browser keeps at most a frame or two in flight, so one round trip says little; the time of
//   the whole run divided by its updates includes the GPU's work: that is the cost per update.
// - heroVsPeer: the hero embed and the three.js peer (bench/peer.html) driven by the same messages,
//   interleaved in rounds so that drift in the machine's load hits both alike; ratio = hero / peer.
// - pageLoad: time from navigation to a panel's first frame (performance mark
//   `fresnel-lab:first-frame:<id>`, set by the panel host), the gzipped JavaScript fetched until
//   then (and until `ready`), and what CSS and fonts were fetched.
// - layoutShift: cumulative layout shift over a full scroll of the lecture page.
import { readFileSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

const HOST_PATH = '__bench-host.html'; // a blank same-origin page for the iframes (routed, not built)

/** Errors any measured page logged (the run fails on them, as the panel benchmark does). */
export const problems = [];

export async function freshContext(browser, viewport) {
  const context = await browser.newContext({ viewport });
  context.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  context.on('weberror', (e) => problems.push(e.error().message));
  return context;
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
export const spread = (xs) => ({ median: median(xs), min: Math.min(...xs), max: Math.max(...xs) });

async function hostPage(browser, base, viewport) {
  const context = await freshContext(browser, viewport);
  await context.route(`${base}${HOST_PATH}`, (route) => route.fulfill({
    contentType: 'text/html', body: '<!doctype html><html><body style="margin:0"></body></html>',
  }));
  const page = await context.newPage();
  await page.goto(`${base}${HOST_PATH}`);
  return { context, page };
}

/** ms per update of the frame at `url`, one sample per run of `updates` set → rendered round trips, after `warmup`. */
function timeUpdates(page, url, { width, height, key, values, updates, warmup, runs = 1 }) {
  return page.evaluate(async (o) => {
    const frame = document.createElement('iframe');
    frame.style.cssText = `width:${o.width}px;height:${o.height}px;border:0;display:block`;
    const next = (type) => new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`no ${type} from ${o.url} within 60 s`)), 60_000);
      const on = (event) => {
        if (event.source !== frame.contentWindow || event.data?.type !== type) return;
        window.removeEventListener('message', on);
        clearTimeout(timer);
        resolve(event.data);
      };
      window.addEventListener('message', on);
    });
    const ready = next('fresnel-lab:ready');
    frame.src = o.url;
    document.body.append(frame);
    await ready;
    let count = 0; // every message changes the value, so every one draws a frame
    const update = async () => {
      const rendered = next('fresnel-lab:rendered');
      count += 1;
      frame.contentWindow.postMessage({ type: 'fresnel-lab:set', params: { [o.key]: o.values[count % o.values.length] } }, '*');
      await rendered;
    };
    for (let i = 0; i < o.warmup; i += 1) await update();
    const samples = [];
    for (let r = 0; r < o.runs; r += 1) {
      const t0 = performance.now();
      for (let i = 0; i < o.updates; i += 1) await update();
      samples.push((performance.now() - t0) / o.updates);
    }
    frame.remove();
    return samples;
  }, { url, width, height, key, values, updates, warmup, runs });
}

/**
 * The hero embed against two peers, all width × height, in `rounds` interleaved rounds: three.js's
 * MeshPhysicalMaterial with a clear coat (bench/peer.html, the look of the hero's coated plastic)
 * and without one (?clearcoat=0, the plainer and cheaper material).
 */
export async function heroVsPeer(browser, base, { width = 1500, height = 600, rounds = 5, updates = 16, warmup = 6 } = {}) {
  const { context, page } = await hostPage(browser, base, { width: width + 40, height: height + 40 });
  const spec = { width, height, key: 'nT', values: [1.45, 1.55, 1.65, 1.75], updates, warmup };
  const hero = [];
  const peer = [];
  const plain = [];
  const ratios = [];
  const plainRatios = [];
  try {
    for (let r = 0; r < rounds; r += 1) {
      const h = await timeUpdates(page, `${base}embed.html?panel=spheres`, spec);
      const p = await timeUpdates(page, `${base}bench/peer.html`, spec);
      const q = await timeUpdates(page, `${base}bench/peer.html?clearcoat=0`, spec);
      hero.push(...h);
      peer.push(...p);
      plain.push(...q);
      ratios.push(h[0] / p[0]);
      plainRatios.push(h[0] / q[0]);
    }
  } finally {
    await context.close();
  }
  const scene = 'three.js MeshPhysicalMaterial, 3 spheres of 64×32 segments, RoomEnvironment through PMREM, antialias';
  return {
    width, height, rounds, updates,
    hero: { msPerUpdate: spread(hero), samples: hero },
    peer: { msPerUpdate: spread(peer), samples: peer, scene: `${scene}, clear coat` },
    plainPeer: { msPerUpdate: spread(plain), samples: plain, scene: `${scene}, no clear coat` },
    ratio: median(hero) / median(peer),
    ratioPerRound: ratios,
    plainRatio: median(hero) / median(plain),
    plainRatioPerRound: plainRatios,
  };
}

/** What each WebGL panel's update costs in an embed of width × height (the key it changes and two values). */
export const PANEL_UPDATES = {
  spheres: { key: 'nT', values: [1.45, 1.55] },
  asphalt: { key: 'nT', values: [1.5, 1.6] },
  'changing-specular': { key: 'nT', values: [1.45, 1.55] },
  'reflect-refract': { key: 'nT', values: [1.3, 1.4] },
  'refraction-waves': { key: 'nT', values: [1.45, 1.55], query: '&play=false' },
  'fresnel-lighting': { key: 'nT', values: [1.45, 1.55] },
  metals: { key: 'nT', values: [1.45, 1.55] },
  'normal-mips': { key: 'lightEl', values: [6, 7], query: '&truth=false' },
};

/**
 * ms per update of every WebGL panel in `runs` interleaved rounds: each round visits every panel
 * once, the hero among them, so a busy spell of the machine falls on all of them alike; `toHero` is
 * a panel's ms over the hero's of the same round (median [min, max] over the rounds). `ids` (the
 * hero first) narrows the panels, as the tiny run does.
 */
export async function panelUpdateCosts(browser, base,
  { width = 1280, height = 720, updates = 12, warmup = 6, runs = 5, ids = Object.keys(PANEL_UPDATES) } = {}) {
  const { context, page } = await hostPage(browser, base, { width: width + 40, height: height + 40 });
  const samples = Object.fromEntries(ids.map((id) => [id, []]));
  try {
    for (let r = 0; r < runs; r += 1) {
      for (const id of ids) {
        const { key, values, query = '' } = PANEL_UPDATES[id];
        const [ms] = await timeUpdates(page, `${base}embed.html?panel=${id}${query}`, { width, height, key, values, updates, warmup });
        samples[id].push(ms);
      }
    }
  } finally {
    await context.close();
  }
  const panels = Object.fromEntries(Object.entries(samples).map(([id, ms]) => [id, {
    msPerUpdate: spread(ms),
    toHero: spread(ms.map((m, r) => m / samples.spheres[r])),
    key: PANEL_UPDATES[id].key,
  }]));
  return { width, height, runs, panels };
}

/** Gzipped size (zlib default level, as a static server sends it) of a built file, by its URL. */
function gzippedBytes(siteDir, base, url) {
  const path = join(siteDir, decodeURIComponent(new URL(url).pathname.slice(new URL(base).pathname.length)));
  return existsSync(path) ? gzipSync(readFileSync(path)).length : 0;
}

/**
 * Loads `url` in a cold context and waits for panel `id`'s first frame (and `ready`). Returns the
 * ms from navigation to that frame, and the gzipped JS (and CSS, fonts) fetched before it and
 * before `ready`.
 */
export async function pageLoad(browser, base, siteDir, url, { id, viewport = { width: 1280, height: 800 } }) {
  const context = await freshContext(browser, viewport);
  try {
    const page = await context.newPage();
    await page.goto(url);
    const readyAt = await page.evaluate(async () => { await window.fresnelLab.ready; return performance.now(); });
    // A build older than the mark has none: then the first frame counts as `ready`.
    await page.waitForFunction((name) => performance.getEntriesByName(name).length > 0, `fresnel-lab:first-frame:${id}`, { timeout: 5_000 })
      .catch(() => {});
    const { firstFrame, resources } = await page.evaluate((name) => ({
      firstFrame: performance.getEntriesByName(name)[0]?.startTime ?? null,
      resources: performance.getEntriesByType('resource').map((r) => ({ url: r.name, start: r.startTime })),
    }), `fresnel-lab:first-frame:${id}`);
    const sum = (until, test) => resources.filter((r) => r.start <= until && test(r.url))
      .reduce((acc, r) => acc + gzippedBytes(siteDir, base, r.url), 0);
    const isJs = (u) => /\.js(\?|$)/.test(u);
    return {
      firstFrameMs: firstFrame,
      jsGzipBeforeFirstFrame: sum(firstFrame ?? readyAt, isJs),
      jsGzipBeforeReady: sum(readyAt, isJs),
      cssGzipBeforeReady: sum(readyAt, (u) => /\.css(\?|$)/.test(u)),
      fontsBeforeReady: resources.filter((r) => r.start <= readyAt && /\.(woff2?|ttf)(\?|$)/.test(r.url)).length,
      scripts: resources.filter((r) => isJs(r.url) && r.start <= readyAt).map((r) => new URL(r.url).pathname.split('/').pop()),
    };
  } finally {
    await context.close();
  }
}

/** Sum of layout-shift values over a scroll of the lecture page from top to bottom, each step waiting for the panels in view to mount. */
export async function layoutShift(browser, base, { viewport = { width: 1280, height: 800 } } = {}) {
  const context = await freshContext(browser, viewport);
  try {
    const page = await context.newPage();
    await page.addInitScript(() => {
      window.__shifts = [];
      new PerformanceObserver((list) => {
        for (const e of list.getEntries()) {
          if (e.hadRecentInput) continue;
          // What moved, so a shift can be traced to its panel: tag.class [section], top before → after.
          const moved = e.sources.map(({ node, previousRect, currentRect }) => {
            const element = node?.nodeType === 1 ? node : node?.parentElement;
            const name = element ? `${element.tagName.toLowerCase()}.${[...element.classList].join('.')}` : '?';
            return `${name} [${element?.closest('section')?.id ?? ''}] ${Math.round(previousRect.y)}→${Math.round(currentRect.y)}`;
          });
          window.__shifts.push({ value: e.value, at: e.startTime, moved });
        }
      }).observe({ type: 'layout-shift', buffered: true });
    });
    await page.goto(base);
    await page.evaluate(() => window.fresnelLab.ready);
    for (;;) {
      const more = await page.evaluate(() => {
        const before = window.scrollY;
        window.scrollBy(0, window.innerHeight * 0.8);
        return window.scrollY > before;
      });
      await page.waitForFunction(() => Object.values(window.fresnelLab.hosts).every((h) => {
        const r = h.container?.getBoundingClientRect?.();
        return !r || r.bottom < 0 || r.top > window.innerHeight || h.mounted;
      }), null, { timeout: 60_000 }).catch(() => {});
      await page.evaluate(() => new Promise((r) => { requestAnimationFrame(() => requestAnimationFrame(r)); }));
      if (!more) break;
    }
    const shifts = await page.evaluate(() => window.__shifts);
    const largest = shifts.reduce((a, s) => (s.value > (a?.value ?? 0) ? s : a), null);
    return { total: shifts.reduce((a, s) => a + s.value, 0), shifts: shifts.length, largest: largest?.value ?? 0, largestMoved: largest?.moved ?? [] };
  } finally {
    await context.close();
  }
}
