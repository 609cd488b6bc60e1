// The accessibility audit: axe-core on the lecture page (scrolled through, so that every panel is
// mounted and seen), on every embed and on the homework page. Any serious or critical violation
// fails; the visible-label rule (label-content-name-mismatch, still marked experimental in axe)
// is on, since a voice-control user says what the control shows.
import AxeBuilder from '@axe-core/playwright';
import { test, expect, openLab } from './fixtures.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';

const EXTRA_RULES = { 'label-content-name-mismatch': { enabled: true }, 'td-has-header': { enabled: true } };

/** The serious and critical violations on the page, each with the first elements it names. */
async function seriousViolations(page) {
  const { violations } = await new AxeBuilder({ page }).options({ rules: EXTRA_RULES }).analyze();
  return violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.help} (${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join('; ')})`);
}

for (const scheme of ['dark', 'light']) {
  test(`the lecture page, scrolled through, ${scheme}`, async ({ page }) => {
    test.setTimeout(180_000);
    await page.addInitScript((theme) => localStorage.setItem('fresnel-lab:theme', JSON.stringify({ scheme: theme })), scheme);
    await openLab(page, './');
    for (const section of await page.locator('section[data-panel]').all()) {
      await section.scrollIntoViewIfNeeded();
      const id = await section.getAttribute('data-panel');
      await expect.poll(() => page.evaluate((panelId) => window.fresnelLab.hosts[panelId].mounted, id), { message: `${id} mounted` }).toBe(true);
    }
    expect(await seriousViolations(page)).toEqual([]);
  });
}

for (const id of PANEL_IDS) {
  test(`the ${id} embed`, async ({ page }) => {
    await openLab(page, `embed.html?panel=${id}`);
    expect(await seriousViolations(page)).toEqual([]);
  });
}

test('the audio trace’s controls, shown', async ({ page }) => {
  await openLab(page, 'embed.html?panel=polarization&audio=1&theme=light');
  await expect(page.locator('.trace-body')).toBeVisible();
  expect(await seriousViolations(page)).toEqual([]);
});

test('the shader lab’s editor in the light theme', async ({ page }) => {
  await openLab(page, 'embed.html?panel=shader-lab&theme=light');
  expect(await seriousViolations(page)).toEqual([]);
});

test('the homework page: the lecturer’s and a student’s sheet', async ({ page }) => {
  await page.goto('homework.html');
  await expect(page.locator('.hw-intro')).toBeVisible();
  expect(await seriousViolations(page)).toEqual([]);
  const sheet = { version: 1, title: 'Week 3', items: [{ question: 'brewster-predict' }, { question: 'exact-r' }] };
  await page.goto(`homework.html?sheet=${Buffer.from(JSON.stringify(sheet)).toString('base64url')}`);
  await expect(page.locator('#question-2')).toBeVisible();
  expect(await seriousViolations(page)).toEqual([]);
});
