// "Export poster": a slide-sized PNG of the view with its link and a QR code that encodes it, for
// hosts that cannot embed a frame.
import { readFileSync } from 'node:fs';
import { test, expect, openLab } from './fixtures.js';
import { POSTER, qrMatrix, qrPlace } from '../../src/host/makePoster.js';

/** Decodes a PNG data URL in the page: its size, and whether each QR module centre is dark. */
const readPoster = (page, url, place, size) => page.evaluate(async ([src, qr, n]) => {
  const image = new Image();
  image.src = src;
  await image.decode();
  const canvas = document.createElement('canvas');
  canvas.width = image.naturalWidth;
  canvas.height = image.naturalHeight;
  const g = canvas.getContext('2d');
  g.drawImage(image, 0, 0);
  const dark = [];
  for (let row = 0; row < n; row += 1) {
    for (let col = 0; col < n; col += 1) {
      const x = qr.x + (col + 4.5) * qr.module;
      const y = qr.y + (row + 4.5) * qr.module;
      dark.push(g.getImageData(Math.floor(x), Math.floor(y), 1, 1).data[0] < 128);
    }
  }
  const centre = g.getImageData(canvas.width / 2, canvas.height / 2 - 100, 1, 1).data;
  return { width: image.naturalWidth, height: image.naturalHeight, dark, centre: [...centre] };
}, [url, place, size]);

test('the poster is slide-sized, shows the picture and carries a QR code of the view\'s link', async ({ page }) => {
  await openLab(page, './embed.html?panel=spheres&nT=1.9');
  const downloading = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Export poster' }).click();
  const download = await downloading;
  expect(download.suggestedFilename()).toBe('fresnel-lab-spheres-poster.png');
  const url = `data:image/png;base64,${readFileSync(await download.path()).toString('base64')}`;
  const link = await page.evaluate(() => window.fresnelLab.hosts.spheres.links().lecture);
  expect(link).toContain('nT=1.9');
  const matrix = await qrMatrix(link);
  const place = qrPlace(matrix.size);
  const poster = await readPoster(page, url, place, matrix.size);
  expect([poster.width, poster.height]).toEqual([POSTER.width, POSTER.height]);
  const expected = [];
  for (let row = 0; row < matrix.size; row += 1) for (let col = 0; col < matrix.size; col += 1) expected.push(matrix.isDark(row, col));
  expect(poster.dark).toEqual(expected);
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
  const matrix = await qrMatrix(link);
  const poster = await readPoster(page, url, qrPlace(matrix.size), matrix.size);
  expect([poster.width, poster.height]).toEqual([POSTER.width, POSTER.height]);
  expect(poster.dark.filter(Boolean).length).toBeGreaterThan(matrix.size * 2);
});
