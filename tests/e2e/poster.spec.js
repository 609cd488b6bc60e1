// "Export poster": a slide-sized PNG of the view with its link and a QR code that encodes it, for
// hosts that cannot embed a frame.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { test, expect, openLab } from './fixtures.js';
import { POSTER } from '../../src/host/makePoster.js';

// jsQR: a QR decoder apart from the generator that drew the code, so the code is read as a phone would.
const JSQR = readFileSync(createRequire(import.meta.url).resolve('jsqr'), 'utf8');

/** Decodes a PNG data URL in the page: its size, the text its QR code holds (or null), a pixel near its middle. */
async function readPoster(page, url) {
  await page.evaluate(JSQR); // defines window.jsQR; run by the test, so the page's script policy does not apply
  return page.evaluate(async (src) => {
    const image = new Image();
    image.src = src;
    await image.decode();
    const [width, height] = [image.naturalWidth, image.naturalHeight];
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    const g = canvas.getContext('2d', { willReadFrequently: true });
    g.drawImage(image, 0, 0);
    const code = window.jsQR(g.getImageData(0, 0, width, height).data, width, height, { inversionAttempts: 'dontInvert' });
    const centre = g.getImageData(width / 2, height / 2 - 100, 1, 1).data;
    return { width, height, text: code?.data ?? null, centre: [...centre] };
  }, url);
}

test('the poster is slide-sized, shows the picture and carries a QR code of the view\'s link', async ({ page }) => {
  await openLab(page, './embed.html?panel=spheres&nT=1.9');
  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Export poster' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('fresnel-lab-spheres-poster.png');
  const url = `data:image/png;base64,${readFileSync(await download.path()).toString('base64')}`;
  const link = await page.evaluate(() => window.fresnelLab.hosts.spheres.links().lecture);
  expect(link).toContain('nT=1.9');
  const poster = await readPoster(page, url);
  expect([poster.width, poster.height]).toEqual([POSTER.width, POSTER.height]);
  expect(poster.text, 'the QR code, decoded').toBe(link);
  // The middle of the poster is the hero's picture, not the plain background.
  const background = await page.evaluate(() => getComputedStyle(document.documentElement).getPropertyValue('--bg').trim());
  expect(background).toMatch(/^#/);
  const bg = [1, 3, 5].map((i) => parseInt(background.slice(i, i + 2), 16));
  expect(poster.centre.slice(0, 3)).not.toEqual(bg);
});

test('a plot-only panel gets a poster of its plot', async ({ page }) => {
  await openLab(page, './embed.html?panel=schlick');
  const url = await page.evaluate(() => window.fresnelLab.hosts.schlick.poster());
  const link = await page.evaluate(() => window.fresnelLab.hosts.schlick.links().lecture);
  const poster = await readPoster(page, url);
  expect([poster.width, poster.height]).toEqual([POSTER.width, POSTER.height]);
  expect(poster.text, 'the QR code, decoded').toBe(link);
});
