import { test, expect, openLab, expectIdle, expectOneFrame } from './fixtures.js';
import { fieldAt, waveField } from '../../src/optics/waves.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const PANEL = 'refraction-waves';
const DEG = Math.PI / 180;
// The shader's palette (display values): dark background and crest colour per medium.
const PALETTE = {
  above: { dark: [0.04, 0.07, 0.13], crest: [0.45, 0.78, 1.0] },
  below: { dark: [0.10, 0.06, 0.02], crest: [1.0, 0.78, 0.40] },
};
const shade = (f, { dark, crest }) => dark.map((d, i) => Math.round(255 * Math.min(1,
  d + (crest[i] - d) * Math.min(1, Math.max(0, f)) + 0.35 * Math.min(1, Math.max(0, f - 1)))));

const frames = (page) => page.evaluate((id) => window.fresnelLab.panels[id].view.frames.frames, PANEL);
const set = (page, values) => page.evaluate(([id, v]) => window.fresnelLab.hosts[id].set(v), [PANEL, values]);

/** Reads the pixels nearest to points given in vacuum wavelengths; returns each pixel-centre point too. */
function probe(page, points) {
  return page.evaluate(([id, pts]) => {
    const { view } = window.fresnelLab.panels[id];
    const [W, H] = view.uniforms.uResolution.value;
    const hh = view.uniforms.uHalfHeight.value;
    const ratio = view.pixelRatio;
    const cssHeight = view.canvas.getBoundingClientRect().height;
    return pts.map(([x, y]) => {
      const i = Math.floor((x / (hh * W / H) * 0.5 + 0.5) * W);
      const j = Math.floor((y / hh * 0.5 + 0.5) * H);
      const at = [(((i + 0.5) / W) * 2 - 1) * hh * W / H, (((j + 0.5) / H) * 2 - 1) * hh];
      return { at, pixel: view.readPixel((i + 0.5) / ratio, cssHeight - (j + 0.5) / ratio), phase: view.uniforms.uPhase.value };
    });
  }, [PANEL, points]);
}

test('30° from air into glass bends to 19.47°, with λ/n and c/n per medium', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  await expect(page.locator('.rw-canvas')).toHaveAttribute('aria-label', /Wavefronts/);
  const summary = page.locator('.rw-summary');
  await expect(summary).toContainText('30.00°');
  await expect(summary).toContainText('19.47°');
  await expect(summary).toContainText('none (ni ≤ nt)'); // n_i, n_t with real subscripts
  await expect(page.locator('.rw-medium-1')).toContainText('λi = λ0/ni = 550.0 nm');
  await expect(page.locator('.rw-medium-2')).toContainText('λt = λ0/nt = 366.7 nm');
  await expect(page.locator('.rw-medium-2')).toContainText('vt = c/nt = 0.667 c');
  await expect(page.locator('.rw-tir')).toBeHidden();
  await expect(page.locator('.panel-description')).toContainText('19.47°');
});

test('glass to air at 60° is total internal reflection (URL honoured)', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&nI=1.5&nT=1&angle=60&play=false`);
  await expect(page.locator('.rw-tir')).toBeVisible();
  await expect(page.locator('.rw-tir')).toContainText('Total internal reflection');
  const summary = page.locator('.rw-summary');
  await expect(summary).toContainText('41.81°');
  await expect(summary).toContainText('none (total internal reflection)');
  await expect(page.locator('.rw-snell')).toContainText('no');
  // Deep below the interface nothing travels under TIR; just inside the critical angle a wave does.
  // Eight points across one period along the interface (2π/kx = 1.04 λ0 at 40°): one is near a crest.
  const row = Array.from({ length: 8 }, (_, i) => [2 + i * 0.13, -2.2]);
  const brightest = (pixels) => Math.max(...pixels.map((p) => p.pixel[0]));
  expect(brightest(await probe(page, row))).toBeLessThan(40);
  await set(page, { angle: 40 });
  await expect(page.locator('.rw-tir')).toBeHidden();
  await expect(summary).toContainText('θt');
  expect(brightest(await probe(page, row))).toBeGreaterThan(200);
});

test('the GPU field matches its JS twin on both sides, reflected wave included', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}&play=false&reflected=true&angle=50&nI=1.2&nT=1.9`);
  // Eight points across one period along the interface (2π/kx = 1/(1.2 sin 50°) λ0) in each medium,
  // so every phase of the wave is probed, the bright half included.
  const period = 1 / (1.2 * Math.sin(50 * DEG));
  const points = Array.from({ length: 8 }, (_, i) => [[-3.5 + (i * period) / 8, 1.3], [1.5 + (i * period) / 8, -1.3]]).flat();
  const w = waveField(50 * DEG, 1.2, 1.9);
  let lit = 0;
  for (const { at, pixel, phase } of await probe(page, points)) {
    const f = fieldAt(w, at[0], at[1], phase, true);
    if (at[1] < 0 && f > 0.1 && f < 0.9) lit += 1;
    const expected = shade(f, at[1] >= 0 ? PALETTE.above : PALETTE.below);
    expect(Math.max(...pixel.slice(0, 3).map((v, i) => Math.abs(v - expected[i])))).toBeLessThanOrEqual(3);
  }
  expect(lit).toBeGreaterThanOrEqual(2); // the transmitted amplitude |t_s| < 1 is visible in these probes
});

test('pause stops the frames, play resumes them', async ({ page }) => {
  await openLab(page, `./embed.html?panel=${PANEL}`);
  const button = page.locator('.rw-play');
  await expect(button).toHaveText(/Pause/);
  const start = await frames(page);
  await expect.poll(() => frames(page)).toBeGreaterThan(start + 2); // SwiftShader: a few frames a second
  await button.click();
  await expect(button).toHaveText(/Play/);
  await expect(page).toHaveURL(/play=false/);
  const paused = await expectIdle(page, PANEL); // a frame already requested may still land first
  // A change while paused draws exactly one frame.
  const input = page.locator('.lil-gui .lil-controller', { hasText: 'Incidence angle' }).locator('input');
  await input.fill('45');
  await input.press('Enter');
  await expect(page.locator('.rw-summary')).toContainText('28.13°'); // asin(sin 45° / 1.5)
  await expectOneFrame(page, PANEL, paused);
  await button.press('Enter');
  await expect(button).toHaveText(/Pause/);
  await expect.poll(() => frames(page)).toBeGreaterThan(paused + 3);
});

test('reduced motion starts on a still frame', async ({ page }) => {
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openLab(page, `./embed.html?panel=${PANEL}&nT=1.333`);
  await expect(page.locator('.rw-play')).toHaveText(/Play/);
  await expect(page.locator('.rw-medium-2')).toContainText('0.750 c');
  const still = await expectIdle(page, PANEL, 42);
  expect(still).toBeGreaterThanOrEqual(1);
  expect(await page.evaluate((id) => window.fresnelLab.panels[id].playing, PANEL)).toBe(false);
});

test('in the pseudo-locale every word is the catalogue\'s: media, button, key numbers, the TIR banner', async ({ page }) => {
  await openInPseudoLocale(page, './embed.html?panel=refraction-waves&play=false');
  expect(await panelWordsOutside(page), 'paused').toEqual([]);
  for (const values of [{ play: true }, { nI: 1.5, nT: 1, angle: 60 }]) {
    await page.evaluate((v) => window.fresnelLab.hosts['refraction-waves'].set(v), values);
    expect(await panelWordsOutside(page), JSON.stringify(values)).toEqual([]);
  }
  await expect(page.locator('.rw-tir')).toBeVisible();
});
