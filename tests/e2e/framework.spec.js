// The lecture page as a whole: lecture-mode keys, the context budget while scrolling, the message
// API of embeds, bad links, themes. (Every panel mounting, here and alone: contract.spec.js; markup
// through each embed's message door: embeds.spec.js.)
import { test, expect, animationFrames, openLab, nextFrames, labReady } from './fixtures.js';
import { embedInDeck } from './deckFrame.js';
import { XSS, injected } from './doorFuzz.js';

/**
 * Bytes the page's own script holds after a garbage collection, from a heap snapshot: objects,
 * closures, arrays and strings. V8's compiled code (which grows while functions warm up, and
 * levels off) and the browser's native buffers (bounded by the browser) are left out.
 */
async function scriptHeap(cdp) {
  await cdp.send('HeapProfiler.collectGarbage');
  const chunks = [];
  const keep = (event) => chunks.push(event.chunk);
  cdp.on('HeapProfiler.addHeapSnapshotChunk', keep);
  await cdp.send('HeapProfiler.takeHeapSnapshot', { reportProgress: false });
  cdp.off('HeapProfiler.addHeapSnapshotChunk', keep);
  const { snapshot: { meta }, nodes } = JSON.parse(chunks.join(''));
  const width = meta.node_fields.length;
  const type = meta.node_fields.indexOf('type');
  const size = meta.node_fields.indexOf('self_size');
  const kinds = meta.node_types[0];
  const held = new Set(['object', 'closure', 'array', 'string', 'concatenated string', 'sliced string', 'regexp', 'number']);
  let bytes = 0;
  for (let i = 0; i < nodes.length; i += width) if (held.has(kinds[nodes[i + type]])) bytes += nodes[i + size];
  return bytes;
}

test('scrolling the whole page four times: never more than 8 live WebGL contexts, none leak, and the heap stops growing', async ({ page }) => {
  test.setTimeout(240_000);
  await openLab(page);
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('HeapProfiler.enable');
  const height = await page.evaluate(() => document.documentElement.scrollHeight);
  const held = [];
  for (let pass = 0; pass < 4; pass += 1) {
    for (let y = 0; y <= height; y += 700) {
      await page.evaluate((top) => window.scrollTo(0, top), y);
      await nextFrames(page); // the observers have seen this position: panels near it mount
    }
    await page.evaluate(() => window.scrollTo(0, 0));
    await nextFrames(page);
    if (pass === 1 || pass === 3) held.push(await scriptHeap(cdp)); // after two passes every panel has mounted and gone twice
  }
  const stats = await page.evaluate(() => ({ ...window.fresnelLab.contexts }));
  console.log(`[contexts] ${JSON.stringify(stats)}; [script heap after passes 2 and 4] ${held.map((b) => `${(b / 1e6).toFixed(3)} MB`).join(', ')}`);
  expect(stats.peak).toBeLessThanOrEqual(8);
  const mountedGl = await page.evaluate(() => Object.values(window.fresnelLab.hosts).filter((h) => h.mounted && h.usesWebGL).length);
  expect(stats.live).toBeLessThanOrEqual(mountedGl); // every context belongs to a mounted panel
  // Each pass mounts and disposes every panel; what they leave behind would add up pass by pass.
  expect(held.at(-1) - held[0], 'bytes the page kept over two more passes').toBeLessThan(40_000);
});

test('with a budget of 2, the farthest WebGL panel gives its context up first', async ({ page }) => {
  test.setTimeout(180_000);
  await page.setViewportSize({ width: 1280, height: 2400 }); // several WebGL panels near at once
  await openLab(page, './?maxContexts=2');
  const gl = await page.evaluate(() => Object.values(window.fresnelLab.hosts).filter((h) => h.usesWebGL).map((h) => h.id));
  expect(gl.length).toBeGreaterThan(3);
  // The WebGL panel nearest the middle of the screen (the last ones cannot reach the middle).
  const nearestGl = () => page.evaluate((ids) => ids.map((id) => {
    const r = document.querySelector(`section[data-panel="${id}"]`).getBoundingClientRect();
    return { id, d: Math.abs(r.top + r.height / 2 - window.innerHeight / 2) };
  }).sort((a, b) => a.d - b.d)[0].id, gl);
  for (const id of gl) {
    await page.locator(`section[data-panel="${id}"]`).evaluate((s) => s.scrollIntoView({ block: 'center' }));
    await nextFrames(page);
    const nearest = await nearestGl();
    await expect.poll(() => page.evaluate((i) => window.fresnelLab.hosts[i].mounted, nearest), { message: nearest }).toBe(true);
    const live = await page.evaluate(() => window.fresnelLab.contexts.live);
    expect(live).toBeLessThanOrEqual(2);
  }
  expect(await page.evaluate(() => window.fresnelLab.contexts.peak)).toBeLessThanOrEqual(2);
});

test('a bad page setting in the link is named and ignored', async ({ page }) => {
  await openLab(page, './?maxContexts=99');
  await expect(page.locator('main > .notice')).toContainText('maxContexts=99 is outside 1 to 8; using 8');
});

test('mounting and disposing a WebGL panel many times leaks no context', async ({ page }) => {
  await openLab(page);
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts.spheres.mounted)).toBe(true);
  const stats = await page.evaluate(async () => {
    const host = window.fresnelLab.hosts.spheres;
    const before = window.fresnelLab.contexts.live;
    for (let i = 0; i < 200; i += 1) {
      host.unmount();
      host.mount();
    }
    await new Promise((r) => requestAnimationFrame(r));
    return { before, after: window.fresnelLab.contexts.live, created: window.fresnelLab.contexts.created };
  });
  expect(stats.after).toBe(stats.before);
  expect(stats.created).toBeGreaterThanOrEqual(200);
});

test('lecture-mode keys move between panels and keep the panel in the hash', async ({ page }) => {
  await openLab(page);
  const ids = await page.evaluate(() => [...document.querySelectorAll('section[data-panel]')].map((s) => s.id)
    .filter((id) => id in window.fresnelLab.hosts));
  await page.locator('h1').click();
  await page.keyboard.press('PageDown');
  await expect(page).toHaveURL(new RegExp(`#${ids[1]}$`));
  await page.keyboard.press('ArrowRight');
  await expect(page).toHaveURL(new RegExp(`#${ids[2]}$`));
  await page.keyboard.press('ArrowUp');
  await expect(page).toHaveURL(new RegExp(`#${ids[1]}$`));
  const top = await page.locator(`section#${ids[1]}`).evaluate((s) => s.getBoundingClientRect().top);
  expect(Math.abs(top)).toBeLessThan(5);
  await page.keyboard.press('h');
  await expect(page.locator('.panel-side').first()).toBeHidden();
  await page.keyboard.press('h');
  await expect(page.locator(`section#${ids[1]} .panel-side`)).toBeVisible();
  // A reload returns to the panel in the hash.
  await page.reload();
  await labReady(page);
  await expect.poll(() => page.locator(`section#${ids[1]}`).evaluate((s) => Math.abs(s.getBoundingClientRect().top))).toBeLessThan(40);
  // Also deep in the page, where the panels above it mount and change height after the load.
  const deep = ids.at(-3); // (the last ones cannot reach the top: the page ends below them)
  await page.goto('about:blank');
  await page.goto(`./#${deep}`);
  await labReady(page);
  // Once every panel within a screen of the view has mounted (they mount on approach), the target
  // is still at the top, and stays there (the window in which it may not move).
  await expect.poll(() => page.evaluate(() => [...document.querySelectorAll('section[data-panel]')].every((s) => {
    const r = s.getBoundingClientRect();
    const near = r.bottom > -window.innerHeight && r.top < 2 * window.innerHeight;
    return !near || window.fresnelLab.hosts[s.dataset.panel].mounted;
  }))).toBe(true);
  const offset = () => page.locator(`section#${deep}`).evaluate((s) => Math.abs(s.getBoundingClientRect().top));
  expect(await offset()).toBeLessThan(40);
  await animationFrames(page, 30); // the page's own frames: layout and scroll anchoring happen in them
  expect(await offset()).toBeLessThan(40);
});

test('the message API sets, gets and rejects, and announces ready and rendered frames', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres');
  expect(await api.waitFor('fresnel-lab:ready')).toMatchObject({ panel: 'spheres', params: { nI: 1, nT: 1.5 } });
  expect((await api.waitFor('fresnel-lab:rendered')).frame).toBeGreaterThanOrEqual(1);
  await api.send({ type: 'fresnel-lab:set', params: { nT: 2.4 } });
  await api.send({ type: 'fresnel-lab:set', params: { nI: 'abc', bogus: 1 } });
  await api.send({ type: 'fresnel-lab:get' });
  const error = await api.waitFor('fresnel-lab:error');
  expect(error.message).toContain('nI');
  expect(error.message).toContain('bogus');
  await api.waitFor('fresnel-lab:state', 3);
  // A change made in the panel itself (here as a control would make it) is announced too.
  await api.frame.evaluate(() => window.fresnelLab.hosts.spheres.set({ nT: 1.9 }, { source: 'user' }));
  await api.waitFor('fresnel-lab:state', 4);
  const states = await api.all('fresnel-lab:state');
  expect(states.at(-2).params).toMatchObject({ nI: 1, nT: 2.4 });
  expect(states.at(-1).params).toMatchObject({ nI: 1, nT: 1.9 });
});

test('a link full of garbage loads with notices and defaults; markup in it is quoted as text', async ({ page }) => {
  // Markup that would set window.__xss or leave elements behind if a notice ever parsed it as HTML.
  const query = new URLSearchParams({
    nT: XSS[0], nI: '-4', kd: XSS[1], errScale: XSS[3], 'metals.n': 'abc', 'schlick.nT': '1e400', 'asphalt.cameraElevation': 'NaN', [XSS[4]]: '1',
  });
  await openLab(page, `./?${query}`);
  const notice = page.locator('section[data-panel="spheres"] .notice');
  await expect(notice).toContainText(`nT=${XSS[0]} is not a number`);
  await expect(notice).toContainText(`kd=${XSS[1]} is not a colour`);
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts.spheres.values }));
  expect(values).toMatchObject({ nI: 1, nT: 1.5, kd: '#a3241c', errScale: 'auto' });
  expect(await injected(page), 'markup in the link became elements').toEqual([]);
});

test('theme and projector mode are remembered across reloads', async ({ page }) => {
  await openLab(page);
  await page.locator('.page-controls').getByLabel('Theme').selectOption('light');
  await page.locator('.page-controls input[type="checkbox"]').check();
  await page.reload();
  await labReady(page);
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'light');
  await expect(page.locator('html')).toHaveClass(/projector/);
  const bg = await page.evaluate(() => getComputedStyle(document.documentElement).backgroundColor);
  expect(bg).toBe('rgb(255, 255, 255)');
});
