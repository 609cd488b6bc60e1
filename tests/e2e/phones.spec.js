// Phones: the hero shows one sphere at a time with a switch, orbits under one finger and zooms
// under two (real touch events through the DevTools protocol), and its controls start folded below
// the picture; a tap reads a picture as hovering does. That every embed fits 390 and 768 px, cuts
// no label and passes the audit there is checked in embeds.spec.js.
import { test, expect, openLab, settledFrames } from './fixtures.js';

// A phone is a context of its own (isMobile, touch).
test.use({ ownPage: true });

test.describe('the hero on a phone', () => {
  test.use({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });

  test('one sphere at a time, switched; the controls folded under the picture', async ({ page }) => {
    await openLab(page, 'embed.html?panel=spheres');
    const switcher = page.getByRole('group', { name: 'Sphere shown' });
    await expect(switcher).toBeVisible();
    await expect(switcher.getByRole('button', { name: 'Exact', exact: true })).toHaveAttribute('aria-pressed', 'true');
    const pickCentre = () => page.evaluate(() => {
      const box = document.querySelector('.stage-canvas').getBoundingClientRect();
      return window.fresnelLab.panels.spheres.trio.pick(box.left + box.width / 2, box.top + box.height / 2)?.mode;
    });
    expect(await pickCentre()).toBe('exact');
    await expect(page.locator('.legend')).toBeHidden();
    await switcher.getByRole('button', { name: '|Exact − Schlick|' }).click();
    expect(await pickCentre()).toBe('error');
    await expect(page.locator('.legend')).toBeVisible();
    await expect(page.locator('.stage-labels span:visible')).toHaveText(['|Exact − Schlick|']);
    // The controls: folded, below the picture, opened by their title.
    const gui = page.locator('.lil-gui.lil-root');
    await expect(gui).toHaveClass(/lil-closed/);
    const stageBottom = (await page.locator('.stage').boundingBox()).y + (await page.locator('.stage').boundingBox()).height;
    expect((await gui.boundingBox()).y).toBeGreaterThanOrEqual(stageBottom);
    await gui.locator('> .lil-title').click();
    await expect(gui).not.toHaveClass(/lil-closed/);
    await expect(gui.getByText('n_t (sphere)')).toBeVisible();
  });

  test('one finger orbits, two fingers pinch to zoom', async ({ page }) => {
    await openLab(page, 'embed.html?panel=spheres');
    await settledFrames(page, 'spheres');
    const box = await page.locator('.stage-canvas').boundingBox();
    const cx = box.x + box.width / 2;
    const cy = box.y + box.height / 2;
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    const values = () => page.evaluate(() => ({ ...window.fresnelLab.hosts.spheres.values }));
    const start = await values();
    await touch('touchStart', [[cx, cy]]);
    for (let i = 1; i <= 5; i += 1) await touch('touchMove', [[cx + i * 12, cy]]);
    await touch('touchEnd', []);
    await expect.poll(async () => (await values()).viewAz).not.toBe(start.viewAz);
    expect((await values()).viewDist).toBe(start.viewDist);
    const orbited = await values();
    await touch('touchStart', [[cx - 30, cy], [cx + 30, cy]]);
    for (let i = 1; i <= 5; i += 1) await touch('touchMove', [[cx - 30 - i * 15, cy], [cx + 30 + i * 15, cy]]);
    await touch('touchEnd', []);
    await expect.poll(async () => (await values()).viewDist).toBeLessThan(start.viewDist); // fingers apart: nearer
    expect((await values()).viewAz).toBe(orbited.viewAz); // a pinch is not an orbit
  });
});

test.describe('reading a picture by touch', () => {
  test.use({ viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });

  test('a tap on the asphalt road reads θd and F there, and the reading stays after the finger lifts', async ({ page }) => {
    await openLab(page, 'embed.html?panel=asphalt');
    const readout = page.locator('.asphalt-readout');
    await expect(readout).toContainText('Hover or tap the road');
    const box = await page.locator('.asphalt-canvas').boundingBox();
    await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height * 0.85); // the near road
    await expect(readout).toHaveText(/^Road [\d.]+ m ahead, seen [\d.]+° below the horizon: θd = [\d.]+°, F = [\d.]+/);
  });

  test('a tap on the hero’s sphere reads that pixel, and the reading stays after the finger lifts', async ({ page }) => {
    await openLab(page, 'embed.html?panel=spheres');
    const readout = page.locator('.readout');
    await expect(readout).toContainText('Hover or tap a sphere');
    const box = await page.locator('.stage-canvas').boundingBox();
    await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
    await expect(readout).toHaveText(/^Pixel: θ = [\d.]+°\s+F exact = [\d.]+/);
  });

  test('a tap on a stability map reads that cell', async ({ page }) => {
    await openLab(page, 'embed.html?panel=stability');
    const readout = page.locator('.st-readout');
    await expect(readout).toContainText('Hover or tap a map');
    const box = await page.locator('.st-canvas').first().boundingBox();
    await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
    await expect(readout).toContainText('θ');
    await expect(readout).not.toContainText('Hover or tap');
  });
});
