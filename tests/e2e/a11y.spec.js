// The accessibility audit (audit.js) on the lecture page, scrolled through so that every panel is
// mounted and seen, on the audio trace, the shader lab's editor in light, and the homework page.
// Every embed is audited in embeds.spec.js, on a desktop, a phone and a tablet.
import { test, expect, openLab, settledFrames } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';
import { seriousViolations } from './audit.js';
import { mountedHeight, reservedHeight } from './layout.js';
import { englishPanelTitle } from './englishText.js';

// One walk down the lecture page with reduced motion: every panel has its section, its place kept
// before it mounts and never taller than it, mounts when it comes near and then settles (nothing
// moves by itself), no CSS animation runs, and the page passes the audit in the dark theme and,
// switched in place, in the light one.
test('the lecture page, scrolled through: every panel mounts and settles, reduced motion holds, audited dark and light', async ({ page }) => {
  test.setTimeout(240_000);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openLab(page, './');
  const sections = await page.evaluate(() => [...document.querySelectorAll('section[data-panel]')].map((s) => ({
    id: s.dataset.panel, heading: s.querySelector('h2').textContent, lede: s.querySelector('.lede').textContent,
  })));
  expect(sections.map((s) => s.id)).toEqual(PANELS.map((p) => p.id));
  await expect(page.locator('main > .notice-error')).toHaveCount(0);
  for (const [i, entry] of PANELS.entries()) {
    expect(sections[i].heading.replace(/\s+/g, ' ')).toBe(englishPanelTitle(entry.id).replace(/_([a-z])/g, '$1'));
    expect(sections[i].lede).toContain('(');
    const reserved = await reservedHeight(page, entry.id); // read before it mounts (loading.spec.js: other widths)
    await page.locator(`section[data-panel="${entry.id}"]`).scrollIntoViewIfNeeded();
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].mounted, entry.id), { message: entry.id }).toBe(true);
    const height = await mountedHeight(page, entry.id);
    expect(reserved, `${entry.id}'s reserved place`).toBeLessThanOrEqual(height);
    expect(reserved, `${entry.id}'s reserved place`).toBeGreaterThan(0.4 * height);
    await expect(page.locator(`section[data-panel="${entry.id}"] .panel-description`)).toHaveText(/\d/);
    await settledFrames(page, entry.id); // throws if it keeps drawing
  }
  expect(await page.evaluate(() => window.fresnelLab.hosts['refraction-waves'].values.play)).toBe(false);
  expect(await page.evaluate(() => document.getAnimations().length)).toBe(0);
  expect(await seriousViolations(page), 'dark').toEqual([]);
  await page.locator('.page-controls').getByLabel('Theme').selectOption('light');
  await expect(page.locator('html')).toHaveAttribute('data-theme', 'light');
  expect(await seriousViolations(page), 'light').toEqual([]);
});

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
