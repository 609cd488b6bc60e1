// Hearing R(θ): the audio trace is off until the A key (or its button, ?audio=1, a message) turns
// it on; the arrow keys move a θ cursor whose value is heard as a pitch and read out; the Brewster
// and critical angles and the total-internal-reflection range have sounds of their own. What is
// heard is read from the page's sound log (a headless browser has no speakers); the values are
// checked against the s and p Fresnel equations written out here (Hecht, Optics §4.6).
import { test, expect, openLab } from './fixtures.js';
import { embedInDeck } from './deckFrame.js';

const DEG = Math.PI / 180;
function rp(thetaDeg, n1, n2) {
  const ci = Math.cos(thetaDeg * DEG);
  const st = (n1 / n2) * Math.sin(thetaDeg * DEG);
  if (st >= 1) return 1;
  const ct = Math.sqrt(1 - st * st);
  return ((n2 * ci - n1 * ct) / (n2 * ci + n1 * ct)) ** 2;
}
const lastSound = (page) => page.evaluate(() => window.fresnelLab.audio.log().at(-1) ?? null);
const press = async (page, key, times = 1) => {
  for (let i = 0; i < times; i += 1) await page.keyboard.press(key);
};

test('glass to air by ear: the Brewster blip, the critical knock and the buzz of total internal reflection', async ({ page }) => {
  await openLab(page, 'embed.html?panel=polarization&nI=1.5&nT=1');
  const trace = page.locator('.trace');
  await expect(trace.locator('.trace-body')).toBeHidden();
  await expect(trace.getByRole('button', { name: 'Hear the curve' })).toHaveAttribute('aria-pressed', 'false');
  expect(await page.evaluate(() => window.fresnelLab.audio.on)).toBe(false);

  await page.keyboard.press('a');
  const cursor = trace.getByRole('slider', { name: 'θ cursor' });
  await expect(cursor).toBeFocused();
  await expect(trace.getByRole('button', { name: 'Hear the curve' })).toHaveAttribute('aria-pressed', 'true');
  await expect(trace.getByRole('combobox', { name: 'Curve' })).toHaveValue('Rp');

  // 0° → 33°: Rp falls, and so does the pitch; nothing is passed yet.
  await press(page, 'ArrowRight', 33);
  const at33 = await lastSound(page);
  expect(at33.cues).toEqual([]);
  expect(at33.hz).toBeCloseTo(220 * 4 ** rp(33, 1.5, 1), 6);
  // 34°: past atan(1/1.5) = 33.69°, the Brewster cue; the pitch is at the bottom (Rp ≈ 0).
  await page.keyboard.press('ArrowRight');
  const at34 = await lastSound(page);
  expect(at34.cues).toEqual(['brewster']);
  expect(at34.hz).toBeCloseTo(220 * 4 ** rp(34, 1.5, 1), 6);
  expect(at34.hz).toBeLessThan(220.1);
  await expect(trace.locator('.trace-readout')).toHaveText(`θ 34.0°: Rp ${rp(34, 1.5, 1).toFixed(4)}. Passed the Brewster angle, 33.69°: Rp is 0 there.`);
  // Back in tenths: silent of landmarks down to 33.7°, the blip again on the step to 33.6°.
  await press(page, 'Shift+ArrowLeft', 3);
  expect((await lastSound(page)).cues).toEqual([]);
  await expect(cursor).toHaveAttribute('aria-valuenow', '33.7');
  await page.keyboard.press('Shift+ArrowLeft');
  expect((await lastSound(page)).cues).toEqual(['brewster']);
  await expect(cursor).toHaveAttribute('aria-valuenow', '33.6');

  // On to 42°: past asin(1/1.5) = 41.81°, the critical cue, then the buzz of the TIR range.
  await press(page, 'ArrowRight', 8);
  await expect(cursor).toHaveAttribute('aria-valuenow', '41.6');
  await page.keyboard.press('ArrowRight');
  const at42 = await lastSound(page);
  expect(at42.cues).toEqual(['critical']);
  expect(at42).toMatchObject({ hz: 880, tir: true });
  await expect(trace.locator('.trace-readout')).toContainText('Passed the critical angle, 41.81°: total internal reflection above it.');
  await page.keyboard.press('PageUp');
  expect(await lastSound(page)).toMatchObject({ hz: 880, tir: true, cues: [] });
  await expect(trace.locator('.trace-readout')).toHaveText('θ 52.6°: Rp 1.0000. Total internal reflection: R = 1.');

  // Space plays the whole curve, with both landmarks in it.
  await page.keyboard.press(' ');
  expect(await lastSound(page)).toMatchObject({ kind: 'sweep', seconds: 3, cues: ['brewster', 'critical'] });
  // The cursor is drawn on the plot; A again turns it all off.
  await page.keyboard.press('a');
  await expect(trace.locator('.trace-body')).toBeHidden();
  expect(await page.evaluate(() => window.fresnelLab.audio.on)).toBe(false);
});

test('the lecture page keeps the trace in its link, and every R(θ) plot has one', async ({ page }) => {
  await openLab(page, './?audio=1');
  expect(await page.evaluate(() => window.fresnelLab.audio.on)).toBe(true);
  for (const id of ['spheres', 'exact-fresnel', 'schlick', 'polarization', 'fresnel-lighting', 'metals']) {
    const section = page.locator(`section[data-panel="${id}"]`);
    await section.scrollIntoViewIfNeeded();
    await expect(section.locator('.trace-body'), `${id} has a trace, shown`).toBeVisible();
  }
  // In the exact-Fresnel panel: the readout is the exact R at the cursor, computed there.
  const exact = page.locator('section[data-panel="exact-fresnel"]');
  await exact.getByRole('slider', { name: 'θ cursor' }).focus();
  await page.keyboard.press('End');
  await expect(exact.locator('.trace-readout')).toHaveText('θ 90.0°: Exact R 1.0000. Passed the Brewster angle, 56.31°: Rp is 0 there.');
  await page.keyboard.press('PageDown');
  const r80 = (rp(80, 1, 1.5) + ((Math.cos(80 * DEG) - Math.sqrt(1.5 ** 2 - Math.sin(80 * DEG) ** 2)) / (Math.cos(80 * DEG) + Math.sqrt(1.5 ** 2 - Math.sin(80 * DEG) ** 2))) ** 2) / 2;
  await expect(exact.locator('.trace-readout')).toHaveText(`θ 80.0°: Exact R ${r80.toFixed(4)}.`);
  // A change of index: the words follow at once.
  await page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].set({ nI: 1.5, nT: 1 }));
  await expect(exact.locator('.trace-readout')).toHaveText('θ 80.0°: Exact R 1.0000. Total internal reflection: R = 1.');
  // Off with A (from the page, not a field): the link forgets it.
  await page.locator('h1').first().click();
  await page.keyboard.press('a');
  expect(await page.evaluate(() => window.fresnelLab.audio.on)).toBe(false);
  await expect.poll(() => new URL(page.url()).searchParams.get('audio')).toBeNull();
  await page.keyboard.press('a');
  await expect.poll(() => new URL(page.url()).searchParams.get('audio')).toBe('1');
});

test('a deck turns the trace on by message and hears when the reader turns it off', async ({ page, baseURL }) => {
  const deck = await embedInDeck(page, baseURL, 'panel=schlick');
  const { frame } = deck;
  await expect(frame.locator('.trace-body')).toBeHidden();
  await deck.send({ type: 'fresnel-lab:audio', on: true });
  await expect(frame.locator('.trace-body')).toBeVisible();
  expect(await deck.count('fresnel-lab:audio')).toBe(0); // the deck's own switch is not echoed
  await frame.getByRole('button', { name: 'Hear the curve' }).click();
  expect(await deck.waitFor('fresnel-lab:audio')).toMatchObject({ panel: 'schlick', on: false });
  await expect(frame.locator('.trace-body')).toBeHidden();
});

test('an embed link with audio=1 starts with the trace on; audio=yes is said and left off', async ({ page }) => {
  await openLab(page, 'embed.html?panel=exact-fresnel&audio=1');
  await expect(page.locator('.trace-body')).toBeVisible();
  await openLab(page, 'embed.html?panel=exact-fresnel&audio=yes');
  await expect(page.locator('.notice')).toContainText('audio');
  await expect(page.locator('.trace-body')).toBeHidden();
});
