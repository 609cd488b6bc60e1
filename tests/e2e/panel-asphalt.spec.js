import { test, expect, openLab, expectIdle, expectOneFrame } from './fixtures.js';
import { expectCachedTerms } from './cachedTerms.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const EMBED = './embed.html?panel=asphalt';
const sum = (rgb) => rgb[0] + rgb[1] + rgb[2];
// Sets values as a control or message would, then reads the pixels around the brightest highlight.
const probeWith = (page, update) => page.evaluate((u) => {
  window.fresnelLab.hosts.asphalt.set(u);
  return window.fresnelLab.panels.asphalt.probePeak();
}, update);

test('mounts in an embed with a labelled canvas and the key numbers', async ({ page }) => {
  await openLab(page, EMBED);
  const canvas = page.locator('.asphalt-canvas');
  await expect(canvas).toBeVisible();
  await expect(canvas).toHaveAttribute('aria-label', /asphalt road/);
  const { centre, peak } = await page.evaluate(() => window.fresnelLab.panels.asphalt.state);
  const entry = (term) => page.locator('.asphalt-summary div', { hasText: term }).locator('dd');
  await expect(entry('F at the view centre')).toHaveText(`${centre.F.toFixed(3)} (θd = ${centre.thetaD.toFixed(1)}°)`);
  await expect(entry('Brightest highlight in view')).toContainText(`specular luminance ${peak.specular.toFixed(3)}`);
  await expect(page.locator('.panel-description')).toContainText('n_t = 1.55 (assumed for bitumen)');
  expect(centre.F).toBeGreaterThan(0.4); // default camera 6° above the road: near grazing
  // The two causes and how little is reflected (physics.js, tests/unit/asphalt.test.js): the lede's figures.
  // At the default view the brightest spot is at the horizon; it is compared with the road seen straight down.
  await expect(entry('Brightest highlight in view')).toContainText('seen at the horizon');
  await expect(entry('Highlight against the road straight below')).toHaveText(/^×21\d\.\d: lobe ×18\.5, F ×11\.7 \(diffuse counted too: ×3\d\.\d\)$/);
  await expect(entry('Sunlight reflected specularly')).toHaveText('7.3 % (diffuse albedo 9.0 %)');
  await expect(page.locator('.panel-description')).toContainText('less than its diffuse albedo of 9.0 %; that light is concentrated');
});

test('how concentrated the light is reads the same from every camera; with n_t = 1 no highlight is named', async ({ page }) => {
  await openLab(page, `${EMBED}&camEl=90`);
  const description = page.locator('.panel-description');
  const shape = async () => (await description.textContent()).replace(/^.*that light is /s, '');
  await expect(description).toContainText('Camera 90° above the road');
  const overhead = await shape();
  expect(overhead).toMatch(/^concentrated: seen from its brightest direction, towards the horizon \(in the limit as the line of sight grazes the road\), the sun's highlight has 90\.4 times/);
  await page.evaluate(() => window.fresnelLab.hosts.asphalt.set({ camEl: 6 }));
  await expect(description).toContainText('Camera 6° above the road');
  expect(await shape()).toBe(overhead);
  await page.evaluate(() => window.fresnelLab.hosts.asphalt.set({ nT: 1 }));
  const entry = (term) => page.locator('.asphalt-summary div', { hasText: term }).locator('dd');
  await expect(entry('Specular reflection')).toHaveText('none: with n_t = 1 the binder matches air, so F = 0 at every angle');
  await expect(page.locator('.asphalt-summary')).not.toContainText('Brightest highlight in view');
  await expect(page.locator('.asphalt-summary')).not.toContainText('Highlight ÷ diffuse');
  await expect(description).toContainText('so the road has no specular reflection');
});

test('the highlight is bright near grazing, absent overhead, and weak without Fresnel', async ({ page }) => {
  await openLab(page, `${EMBED}&camEl=90`);
  const overhead = await probeWith(page, {});
  const grazing = await probeWith(page, { camEl: 3 });
  const noFresnel = await probeWith(page, { fresnel: false });
  expect(sum(grazing)).toBeGreaterThan(sum(overhead) + 300);
  expect(sum(grazing)).toBeGreaterThan(sum(noFresnel) + 150);
  expect(sum(noFresnel)).toBeGreaterThan(sum(overhead)); // still a faint sheen: D and G alone
  const { centre } = await page.evaluate(() => window.fresnelLab.panels.asphalt.state);
  expect(centre.F).toBeCloseTo(((1.55 - 1) / (1.55 + 1)) ** 2, 12); // Fresnel off: R0 everywhere
});

test('the Fresnel checkbox changes the picture, the badge and the link', async ({ page }) => {
  await openLab(page, EMBED);
  const before = await page.evaluate(() => window.fresnelLab.panels.asphalt.probePeak());
  await page.locator('.lil-gui .lil-controller', { hasText: 'Fresnel on' }).locator('input').click();
  await expect(page.locator('.asphalt-badge')).toContainText('Fresnel off: F = R0 = 0.047');
  const after = await page.evaluate(() => window.fresnelLab.panels.asphalt.probePeak());
  expect(sum(before) - sum(after)).toBeGreaterThan(150);
  await expect(page).toHaveURL(/fresnel=false/);
});

test('hovering the road reads θd and F there; the sky has none', async ({ page }) => {
  await openLab(page, `${EMBED}&camEl=4`);
  const box = await page.locator('.asphalt-canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.7);
  const readout = page.locator('.asphalt-readout');
  await expect(readout).toContainText(/Road [\d.]+ m ahead, seen [\d.]+° below the horizon: θd = [\d.]+°, F = 0\.\d{3}/);
  const text = await readout.textContent();
  const thetaD = Number(/θd = ([\d.]+)°/.exec(text)[1]);
  expect(thetaD).toBeGreaterThan(75);
  await page.mouse.move(box.x + box.width / 2, box.y + 10);
  await expect(readout).toContainText('Sky');
});

test('URL parameters are honoured', async ({ page }) => {
  await openLab(page, `${EMBED}&camEl=3&sunEl=15&roughness=0.5&nT=1.6&fresnel=false`);
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts.asphalt.values }));
  expect(values).toEqual({ camEl: 3, sunEl: 15, roughness: 0.5, nT: 1.6, fresnel: false });
  await expect(page.locator('.asphalt-badge')).toContainText('F = R0 = 0.053');
  await expect(page.locator('.lil-gui .lil-controller', { hasText: 'Camera elevation' }).locator('input')).toHaveValue('3');
});

test('nothing draws while nothing changes; the arrow keys move the camera', async ({ page }) => {
  await openLab(page, EMBED);
  const idle = await expectIdle(page, 'asphalt');
  await page.locator('.asphalt-canvas').focus();
  await page.keyboard.press('Shift+ArrowUp');
  await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts.asphalt.values.camEl)).toBe(11);
  await expect(page.locator('.asphalt-summary')).toContainText('θd = 79.5°');
  await expectOneFrame(page, 'asphalt', idle);
});

test('dispose frees the WebGL context and a remount works', async ({ page }) => {
  await openLab(page, EMBED);
  const live = await page.evaluate(() => {
    const host = window.fresnelLab.hosts.asphalt;
    const before = window.fresnelLab.contexts.live;
    host.unmount();
    const after = window.fresnelLab.contexts.live;
    host.mount();
    return [before, after, window.fresnelLab.contexts.live];
  });
  expect(live).toEqual([1, 0, 1]);
  await expect(page.locator('.asphalt-canvas')).toHaveCount(1);
});

test('n and the Fresnel switch redraw only F over cached terms, and the picture is the one-pass picture', async ({ page, browser }) => {
  await expectCachedTerms(page, browser, {
    id: 'asphalt', url: EMBED, changes: [{ nT: 1.33, fresnel: false }, { fresnel: true }], live: { nT: 1.6 }, view: { camEl: 12 },
  });
});

test('in the pseudo-locale every word is the catalogue\'s: key numbers, readouts, notes, description', async ({ page }) => {
  await openInPseudoLocale(page, EMBED);
  expect(await panelWordsOutside(page), 'as it opens').toEqual([]);
  const box = await page.locator('.asphalt-canvas').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.7);
  await expect(page.locator('.asphalt-readout')).toContainText('0');
  expect(await panelWordsOutside(page), 'over the road').toEqual([]);
  await page.mouse.move(box.x + box.width / 2, box.y + 10);
  expect(await panelWordsOutside(page), 'over the sky').toEqual([]);
  for (const values of [{ fresnel: false }, { fresnel: true, sunEl: 2 }, { sunEl: 30, roughness: 0.3 }, { nT: 1 }]) {
    await page.evaluate((v) => window.fresnelLab.hosts.asphalt.set(v), values);
    expect(await panelWordsOutside(page), JSON.stringify(values)).toEqual([]);
  }
});
