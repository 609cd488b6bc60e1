import { test, expect, expectOneFrame, openLab, settledFrames } from './fixtures.js';
import { compare } from './cachedTerms.js';

// The hero keeps its sky between frames (createBackdrop.js) and redraws only the squares round the
// spheres when the optics change. Its picture must be the one-pass picture, byte for byte, in every
// layout, and a change of the view (which moves the sky) must draw the sky again.

/** The hero's picture as drawn (kept sky and squares) and in one full-screen pass, base64 RGBA. */
function bothPictures(page, view, single) {
  return page.evaluate(([v, s]) => {
    const { trio } = window.fresnelLab.panels.spheres;
    trio.setView(v, { silent: true });
    trio.setSingle(s);
    const { gl } = trio.shaderView;
    const read = () => {
      const out = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
      gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA, gl.UNSIGNED_BYTE, out);
      let binary = '';
      for (let i = 0; i < out.length; i += 0x8000) binary += String.fromCharCode(...out.subarray(i, i + 0x8000));
      return btoa(binary);
    };
    trio.shaderView.drawNow();
    const kept = read();
    trio.shaderView.drawOnePass();
    return [kept, read()];
  }, [view, single]);
}

test('the kept sky and the squares make the one-pass picture, in every layout', async ({ page }) => {
  await page.setViewportSize({ width: 900, height: 560 });
  await openLab(page, 'embed.html?panel=spheres&nI=1.5&nT=1&errScale=auto');
  const cases = [
    [{ azimuth: 0, elevation: 15, distance: 6 }, null],
    [{ azimuth: 35, elevation: -40, distance: 2.2 }, null], // the spheres overflow their views
    [{ azimuth: -150, elevation: 80, distance: 10 }, 'error'],
    [{ azimuth: 90, elevation: 5, distance: 3 }, 'schlick'],
  ];
  for (const [view, single] of cases) {
    const [kept, whole] = (await bothPictures(page, view, single)).map((b) => Buffer.from(b, 'base64'));
    const { largest, sameSize } = compare(kept, whole);
    expect(sameSize).toBe(true);
    expect(largest, `${JSON.stringify(view)} ${single}`).toBe(0);
  }
});

test('a change of n redraws the squares over the kept sky; a change of view draws the sky again', async ({ page }) => {
  await openLab(page, 'embed.html?panel=spheres');
  const skies = () => page.evaluate(() => window.fresnelLab.panels.spheres.trio.shaderView.backdropDrawn);
  for (const [params, drawn] of [[{ nT: 1.7 }, 0], [{ viewAz: 40 }, 1], [{ kd: '#2040a0' }, 0], [{ lightEl: 20 }, 1]]) {
    // Whatever the page was still doing (a late layout's resize draws the sky again) ends first.
    const frames = await settledFrames(page, 'spheres');
    const sky = await skies();
    await page.evaluate((p) => window.fresnelLab.hosts.spheres.set(p), params);
    await expectOneFrame(page, 'spheres', frames);
    expect(await skies(), JSON.stringify(params)).toBe(sky + drawn);
  }
});
