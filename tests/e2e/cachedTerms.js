// For panels whose view keeps terms in a float target (createShaderView's `cache`): the picture
// after some changes, read whole, in this page and in a page without float render targets, where
// the same fragment does everything in one pass.
import { expect, openLab } from './fixtures.js';

/**
 * Every pixel (RGBA bytes) of panel `id`'s view after host.set(params) for each params in turn. The
 * bytes come out of the page as base64 (a megabyte as a JSON array of numbers takes seconds).
 */
export async function pixelsAfter(page, id, changes) {
  const base64 = await page.evaluate(([pid, list]) => {
    for (const params of list) window.fresnelLab.hosts[pid].set(params);
    const { view } = window.fresnelLab.panels[pid];
    view.drawNow();
    const { gl } = view;
    const out = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
    gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, out);
    let binary = '';
    for (let i = 0; i < out.length; i += 0x8000) binary += String.fromCharCode(...out.subarray(i, i + 0x8000));
    return btoa(binary);
  }, [id, changes]);
  return Buffer.from(base64, 'base64');
}

/** A page of its own in which EXT_color_buffer_float is missing; close its context when done. */
export async function onePassPage(browser, viewport) {
  const context = await browser.newContext({ viewport });
  await context.addInitScript(() => {
    const original = WebGL2RenderingContext.prototype.getExtension;
    WebGL2RenderingContext.prototype.getExtension = function getExtension(name) {
      return name === 'EXT_color_buffer_float' ? null : original.call(this, name);
    };
  });
  return { page: await context.newPage(), close: () => context.close() };
}

/** How far apart two pictures are: the largest byte difference and the share of bytes that differ. */
export function compare(a, b) {
  let differing = 0;
  let largest = 0;
  for (let i = 0; i < a.length; i += 1) {
    const d = Math.abs(a[i] - b[i]);
    if (d > 0) differing += 1;
    largest = Math.max(largest, d);
  }
  return { largest, share: differing / a.length, sameSize: a.length === b.length };
}

/** Frames drawn and cached-terms draws of panel `id`, to see which changes redraw the terms. */
export function counts(page, id) {
  return page.evaluate((pid) => ({
    frames: window.fresnelLab.hosts[pid].frames, terms: window.fresnelLab.panels[pid].view.termsDrawn,
  }), id);
}

/**
 * The split picture is the one-pass picture after `changes` (at most a rounding step apart), a
 * change of a live uniform (`live`) draws a frame over the kept terms, and a change of the view
 * (`view`) draws the terms again.
 */
export async function expectCachedTerms(page, browser, { id, url, changes, live, view }) {
  await openLab(page, url);
  const split = await pixelsAfter(page, id, changes);
  const onePass = await onePassPage(browser, page.viewportSize());
  await openLab(onePass.page, url);
  const whole = await pixelsAfter(onePass.page, id, changes);
  await onePass.close();
  const { largest, share, sameSize } = compare(split, whole);
  expect(sameSize).toBe(true);
  expect(largest).toBeLessThanOrEqual(1); // float32 terms stored and read back exactly
  expect(share).toBeLessThan(1e-3);
  for (const [params, termsDrawn] of [[live, 0], [view, 1]]) {
    const before = await counts(page, id);
    await page.evaluate(([pid, p]) => window.fresnelLab.hosts[pid].set(p), [id, params]);
    await expect.poll(async () => (await counts(page, id)).frames).toBeGreaterThan(before.frames);
    expect((await counts(page, id)).terms).toBe(before.terms + termsDrawn);
  }
}
