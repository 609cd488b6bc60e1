// Shared browser-test fixture: fails a test on any console error or page error (but those a fault
// test expects: test.use({ allowedErrors })), and logs the WebGL renderer string once per run so
// every report says what it ran on.
//
// Tests share one page per worker (reusablePage.js): its browser tab, script caches and compiled
// code stay warm, which halves what a page load costs a test. It starts each test blank, as a new
// one would: on about:blank, its storage and cookies cleared, the test's viewport, no emulated
// media, no init script or route of the test before. A test that needs a context of its own (a
// locale, a phone, a count of what a cold visit fetches) says so with test.use({ ownPage: true }).
import { test as base, expect } from '@playwright/test';
import { blankPage, guardShared, releasePage } from './reusablePage.js';

let rendererLogged = false;

export const test = base.extend({
  allowedErrors: [null, { option: true }],
  ownPage: [false, { option: true }],
  // The worker's shared tab, made when a test first asks for it.
  shared: [async ({ browser }, use, workerInfo) => {
    const { baseURL, viewport } = workerInfo.project.use;
    const state = { context: await browser.newContext({ baseURL, viewport }), page: null };
    await use(state);
    await state.context.close();
  }, { scope: 'worker' }],
  page: async ({ browser, shared, ownPage, baseURL, viewport, locale, isMobile, hasTouch, allowedErrors }, use, testInfo) => {
    const own = ownPage ? await browser.newContext({ baseURL, viewport, locale, isMobile, hasTouch }) : null;
    if (!own && (locale !== 'en-US' || isMobile || hasTouch)) {
      throw new Error('a test with its own locale or a phone needs test.use({ ownPage: true })');
    }
    const page = own ? await own.newPage() : await blankPage(shared, baseURL, viewport);
    const restore = own ? async () => {} : guardShared(page);
    const problems = [];
    const onConsole = (message) => { if (message.type() === 'error') problems.push(`console error: ${message.text()}`); };
    const onError = (error) => problems.push(`page error: ${error.message}`);
    page.on('console', onConsole);
    page.on('pageerror', onError);
    try {
      await use(page);
    } finally {
      await restore();
      page.off('console', onConsole);
      page.off('pageerror', onError);
      if (own) await own.close();
      else await releasePage(shared, testInfo.status === testInfo.expectedStatus);
    }
    const unexpected = problems.filter((problem) => !allowedErrors?.test(problem));
    expect(unexpected, 'the page logged errors').toEqual([]);
  },
});

/**
 * Waits for the page's script to start (a language other than English is fetched first, so
 * window.fresnelLab may not exist yet when a navigation ends) and for everything it loads.
 */
export async function labReady(page) {
  await page.waitForFunction(() => Boolean(window.fresnelLab?.ready));
  await page.evaluate(() => window.fresnelLab.ready);
}

/** Opens a page, waits for its panels, and logs the WebGL renderer once. */
export async function openLab(page, path = './') {
  await page.goto(path);
  await labReady(page);
  if (!rendererLogged) {
    rendererLogged = true;
    const renderer = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return 'no WebGL2';
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      return `${gl.getParameter(gl.VERSION)} | ${info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)}`;
    });
    console.log(`[webgl] ${renderer}`);
  }
}

/**
 * Waits until panel `id` has drawn nothing for `ticks` animation frames in a row (a requested frame
 * is drawn on the next one), and returns its frame count. A condition, not a sleep: on a slow
 * machine it simply takes more frames.
 */
export async function settledFrames(page, id, { ticks = 10, timeout = 60_000 } = {}) {
  return page.evaluate(async ([panelId, quiet, limit]) => {
    const host = window.fresnelLab.hosts[panelId];
    const nextFrame = () => new Promise((resolve) => { requestAnimationFrame(resolve); });
    const start = performance.now();
    let last = host.frames;
    for (let still = 0; still < quiet;) {
      await nextFrame();
      if (host.frames === last) still += 1;
      else [last, still] = [host.frames, 0];
      if (performance.now() - start > limit) throw new Error(`${panelId} kept drawing for ${limit} ms`);
    }
    return last;
  }, [id, ticks, timeout]);
}

/** Panel `id`'s frame count (every frame its picture draws: ctx.frameDrawn). */
export const hostFrames = (page, id) => page.evaluate((panelId) => window.fresnelLab.hosts[panelId].frames, id);

/**
 * Waits `count` animation frames of the page. The page's own frames, not the clock: a frame a
 * panel requests is drawn on the next one, and on a slow or busy machine the window grows with the
 * page rather than passing before the page has done anything.
 */
export const animationFrames = (page, count) => page.evaluate(async (n) => {
  for (let i = 0; i < n; i += 1) await new Promise((resolve) => { requestAnimationFrame(resolve); });
}, count);

/**
 * Lets panel `id` settle, then checks that it draws nothing for `frames` more animation frames.
 * Returns the frame count.
 */
export async function expectIdle(page, id, frames = 40) {
  const idle = await settledFrames(page, id);
  await animationFrames(page, frames);
  expect(await hostFrames(page, id), `${id} drew while nothing changed`).toBe(idle);
  return idle;
}

/**
 * After a change: waits for its frame, then checks over `frames` animation frames that it was one
 * frame and no more followed.
 */
export async function expectOneFrame(page, id, from, frames = 30) {
  await expect.poll(() => hostFrames(page, id), { message: `${id} drew the change` }).toBeGreaterThan(from);
  await animationFrames(page, frames);
  expect(await hostFrames(page, id), `${id} drew the change once`).toBe(from + 1);
}

/** Two animation frames: observers and requested frames of the last change have run. */
export const nextFrames = (page) => page.evaluate(() => new Promise((resolve) => {
  requestAnimationFrame(() => requestAnimationFrame(resolve));
}));

/**
 * The formulas in `scope` typeset and laid out in KaTeX's fonts: each shows its TeX source until
 * KaTeX (fetched after the picture) typesets it, and the fonts, asked for once the typeset formulas
 * are laid out, change line heights when they arrive. A layout measured before this may move.
 */
export async function typesetSettled(page, scope) {
  await expect(page.locator(`${scope} [aria-busy="true"]`)).toHaveCount(0);
  await expect.poll(() => page.evaluate(async () => {
    await new Promise((resolve) => { requestAnimationFrame(() => requestAnimationFrame(resolve)); });
    await document.fonts.ready;
    return document.fonts.check('16px KaTeX_Main');
  }), { message: 'KaTeX\'s fonts loaded' }).toBe(true);
}

/** A stand-in slide deck on the lab's own origin (served by the test, not part of the site), opened in page. */
export async function openDeck(page) {
  await page.route('**/deck-under-test.html', (route) => route.fulfill({
    contentType: 'text/html', body: '<!doctype html><title>Deck</title><link rel="icon" href="data:,"><body></body>',
  }));
  await page.goto('./deck-under-test.html');
}

export { expect };
