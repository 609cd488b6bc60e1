import { test, expect, openLab, expectIdle, expectOneFrame } from './fixtures.js';

const ID = 'fresnel-lighting';
const embed = (query = '') => `./embed.html?panel=${ID}${query}`;

// Pixels at view angle θ on each sphere (0 = Fresnel, left; 1 = constant weight, right), read from
// the canvas. The upper rim mirrors the sky, so a coat that reflects more there looks whiter.
async function probes(page, rimDeg = 80) {
  return page.evaluate((theta) => {
    const { stage } = window.fresnelLab.panels['fresnel-lighting'];
    return {
      centre: [stage.readAt(0, 0), stage.readAt(1, 0)],
      rim: [stage.readAt(0, theta), stage.readAt(1, theta)],
    };
  }, rimDeg);
}
const sum = (p) => p[0] + p[1] + p[2];
const whiteness = (p) => (p[1] + p[2]) / (2 * p[0]); // toward ks (white) from kd (red)
const diff = (a, b) => a.slice(0, 3).reduce((s, v, i) => s + Math.abs(v - b[i]), 0);

test('the Fresnel rim turns toward ks; the constant-weight rim does not', async ({ page }) => {
  await openLab(page, embed());
  await expect(page.locator('.twin-stage-canvas')).toBeVisible();
  const p = await probes(page);
  // w = 0.04 = F(0°) for n = 1.5: the centres are the same mix.
  expect(diff(p.centre[0], p.centre[1])).toBeLessThanOrEqual(3);
  // Fresnel: the rim (F = 0.39 at 80°) is much brighter and whiter than the centre.
  expect(sum(p.rim[0]) / sum(p.centre[0])).toBeGreaterThan(1.3);
  expect(whiteness(p.rim[0])).toBeGreaterThan(2 * whiteness(p.centre[0]));
  // Constant weight: rim and centre are the same mix (brightness and hue within a few percent).
  expect(sum(p.rim[1]) / sum(p.centre[1])).toBeGreaterThan(0.8);
  expect(sum(p.rim[1]) / sum(p.centre[1])).toBeLessThan(1.15);
  expect(Math.abs(whiteness(p.rim[1]) - whiteness(p.centre[1]))).toBeLessThan(0.1);
  const text = page.locator('.panel-description');
  await expect(text).toContainText('0.0400 at 0°');
  await expect(text).toContainText('0.3877 at 80°'); // fresnelExact(cos 80°, 1, 1.5)
});

test('with n_t = 1 nothing turns toward ks, and the words say so; Schlick\'s form still turns it, and they say why', async ({ page }) => {
  await openLab(page, embed('&nT=1'));
  await expect(page.locator('.twin-stage-canvas')).toBeVisible();
  const text = page.locator('.panel-description');
  await expect(text).toContainText('F = 0 at every angle, since with n_t = 1 the coat matches air and reflects nothing');
  await expect(text).not.toContainText('so its rim turns toward ks');
  const matched = await probes(page);
  // Exact F = 0: the rim is the base colour kd, as red as the centre.
  expect(Math.abs(whiteness(matched.rim[0]) - whiteness(matched.centre[0]))).toBeLessThan(0.1);
  await page.evaluate(() => window.fresnelLab.hosts['fresnel-lighting'].set({ method: 'schlick' }));
  // Schlick at R0 = 0: (1 − cos 80°)⁵ = 0.3853, a whiter rim the exact F would not give.
  await expect(text).toContainText('F is 0.0000 at 0° and 0.3853 at 80°, so its rim turns toward ks, although a coat of n_t = 1');
  await expect(page.locator('.fl-panel .lecture-note')).toContainText('with Schlick\'s form, chosen above, its rim still turns toward ks');
  const schlick = await probes(page);
  expect(whiteness(schlick.rim[0])).toBeGreaterThan(2 * whiteness(schlick.centre[0]));
});

test('the GLSL shown is the GLSL compiled, and Copy GLSL copies it', async ({ page }) => {
  await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
  await openLab(page, embed());
  const code = page.locator('.fl-panel pre code');
  await expect(code).toContainText('mix(kd, ks,');
  await expect(code).toContainText('fresnelExact(dot(N, V), 1.0, n)');
  const shown = await code.textContent();
  const compiled = await page.evaluate(() => {
    const { gl, program } = window.fresnelLab.panels['fresnel-lighting'].stage.view;
    return gl.getAttachedShaders(program).map((s) => gl.getShaderSource(s)).join('\n');
  });
  expect(compiled).toContain(shown);
  const button = page.getByRole('button', { name: 'Copy GLSL' });
  await expect(button).toHaveText('Copy GLSL');
  await button.click();
  await expect(page.locator('.fl-copy-status')).toHaveText('Copied');
  expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(shown);
});

test('controls change the picture and the numbers', async ({ page }) => {
  await openLab(page, embed());
  const before = await probes(page);
  const weight = page.locator('.lil-gui .lil-controller', { hasText: 'Constant ks weight' }).locator('input');
  await weight.fill('0.5');
  await weight.press('Enter');
  await expect(page.locator('.twin-stage-labels')).toContainText('mix(kd, ks, 0.500)');
  const half = await probes(page);
  expect(diff(half.centre[1], before.centre[1])).toBeGreaterThan(60); // halfway to the white coat
  expect(diff(half.centre[0], before.centre[0])).toBeLessThanOrEqual(3); // the Fresnel sphere is unchanged
  await page.evaluate(() => window.fresnelLab.hosts['fresnel-lighting'].set({ ks: '00ff00' }));
  const green = await probes(page);
  // A green coat: the Fresnel rim, mostly coat, loses its blue; its centre, mostly kd, barely changes.
  const rimBlueLost = half.rim[0][2] - green.rim[0][2];
  const centreBlueLost = half.centre[0][2] - green.centre[0][2];
  expect(rimBlueLost).toBeGreaterThan(40);
  expect(rimBlueLost).toBeGreaterThan(2 * centreBlueLost);
  await page.locator('.lil-gui button', { hasText: 'Set w = F(0°)' }).click();
  await expect(page.locator('.fl-summary')).toContainText('0.040 at every angle');
});

test('the URL sets n, the method and the weight', async ({ page }) => {
  await openLab(page, embed('&nT=2.4&method=schlick&weight=0.2&kd=1f4fa3'));
  const values = await page.evaluate(() => ({ ...window.fresnelLab.hosts['fresnel-lighting'].values }));
  expect(values).toMatchObject({ nT: 2.4, method: 'schlick', weight: 0.2, kd: '#1f4fa3' });
  await expect(page.locator('.fl-summary')).toContainText('0.1696'); // R0 for n = 2.4
  await expect(page.locator('.twin-stage-labels')).toContainText('F Schlick');
  await expect(page.locator('.panel-description')).toContainText("Schlick's approximation");
  await expect(page.locator('.fl-panel pre code .fl-live').first()).toContainText('kSchlick');
  const p = await probes(page);
  expect(p.centre[0][2]).toBeGreaterThan(p.centre[0][0]); // the blue kd from the URL
});

test('the layered coat darkens the base beside the lecture\'s mix, and the note says where the lecture is loose', async ({ page }) => {
  await openLab(page, embed());
  const note = page.locator('.fl-panel .lecture-note');
  await expect(note).toContainText("The lecture's k = mix(kd, ks, F) is a heuristic");
  await expect(note).toContainText('sends 0.60 of that diffuse light back'); // hemisphericalReflectance(1.5, 1) = 0.5963
  await expect(note.locator('cite')).toContainText('Weidlich & Wilkie');
  const mix = await probes(page);
  await page.evaluate(() => window.fresnelLab.hosts['fresnel-lighting'].set({ method: 'layered' }));
  await expect(page.locator('.twin-stage-labels')).toContainText('Layered coat, F exact');
  await expect(page.locator('.fl-summary')).toContainText('0.5963 of diffuse light');
  await expect(page.locator('.fl-panel pre code .fl-live', { hasText: 'vec3 kLayered' })).toHaveCount(1);
  await expect(page.locator('.fl-panel pre code .fl-live', { hasText: 'kExact' })).toHaveCount(0);
  const layered = await probes(page);
  // The red base under the coat: its diffuse light crosses the coat twice and spreads out (1/n²),
  // so the centre's red drops well below the lecture's mix; the constant-weight sphere is unchanged.
  expect(layered.centre[0][0]).toBeLessThan(mix.centre[0][0] - 20);
  expect(diff(layered.centre[1], mix.centre[1])).toBeLessThanOrEqual(3);
});

test('nothing draws while nothing changes', async ({ page }) => {
  await openLab(page, embed());
  const idle = await expectIdle(page, 'fresnel-lighting');
  await page.evaluate(() => window.fresnelLab.hosts['fresnel-lighting'].set({ lightAz: 90, nT: 1.7 }));
  await expectOneFrame(page, 'fresnel-lighting', idle);
});
