// Keyboard only, at random but reproducibly: seeded presses of Tab, Shift+Tab, the arrows, the
// Page keys, Home, End, Space, Enter and the digits over the lecture page and every embed. After
// them: no error (the fixture), no NaN or "undefined" on screen or in an accessible name, no panel
// failed, and every value inside its schema. FUZZ_SEED=<n> replays one run. Also: Tab and
// Shift+Tab go round every page (focus is never trapped), and with reduced motion nothing moves
// by itself.
import { test, expect, openLab, settledFrames } from './fixtures.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';
import { seededRandom } from '../../src/homework/seededRandom.js';

const SEED = Number(process.env.FUZZ_SEED ?? 20261203);
const KEYS = ['Tab', 'Tab', 'Tab', 'Shift+Tab', 'ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown',
  'Home', 'End', ' ', 'Enter', '0', '1', '2', '3', '4', '5', '6', '7', '8', '9'];

// Words the page means: prose about NaN, the stability map's class, an exercise's criterion.
const MEANT = [/returns NaN/g, /NaN or infinite/g, /\(no NaN[^)]*\)/g, /NaN\/∞/g];

/** Text on screen and in accessible names and values, with the meant words taken out. */
const shownText = (page) => page.evaluate(() => {
  const named = [...document.querySelectorAll('[aria-label], [aria-valuetext], [aria-valuenow], [title]')]
    .map((e) => ['aria-label', 'aria-valuetext', 'aria-valuenow', 'title'].map((a) => e.getAttribute(a) ?? '').join(' '));
  const descriptions = [...document.querySelectorAll('.panel-description, [id$="-description"]')].map((e) => e.textContent);
  return [document.body.innerText, ...named, ...descriptions].join('\n');
});

/** Every host's values checked against its schema, here and not by the page's own code. */
const outsideSchema = (page) => page.evaluate(() => {
  const bad = [];
  for (const [id, host] of Object.entries(window.fresnelLab.hosts)) {
    for (const [key, spec] of Object.entries(host.panel.schema)) {
      const v = host.values[key];
      const options = Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options ?? {});
      const ok = spec.type === 'number' ? Number.isFinite(v) && v >= spec.min && v <= spec.max
        : spec.type === 'enum' ? options.includes(String(v))
          : spec.type === 'color' ? /^#[0-9a-f]{6}$/.test(v)
            : spec.type === 'boolean' ? typeof v === 'boolean'
              : typeof v === 'string' && (spec.maxLength === undefined || v.length <= spec.maxLength);
      if (!ok) bad.push(`${id}.${key} = ${JSON.stringify(v)}`);
    }
  }
  return bad;
});

async function fuzz(page, seed, presses) {
  const { next } = seededRandom(seed);
  const pressed = [];
  for (let i = 0; i < presses; i += 1) {
    let key = KEYS[Math.floor(next() * KEYS.length)];
    // A link would leave the page under test; Tab past it instead.
    const onLink = await page.evaluate(() => Boolean(document.activeElement?.closest('a[href]')));
    if (onLink && (key === 'Enter' || key === ' ')) key = 'Tab';
    pressed.push(key);
    await page.keyboard.press(key);
  }
  return pressed;
}

async function expectSound(page, what) {
  let text = await shownText(page);
  for (const meant of MEANT) text = text.replace(meant, '');
  expect(text.match(/.{0,40}\b(NaN|undefined)\b.{0,40}/g), `${what}: NaN or undefined shown`).toBeNull();
  expect(await outsideSchema(page), `${what}: values outside their schema`).toEqual([]);
  await expect(page.locator('.notice-error'), `${what}: a panel failed`).toHaveCount(0);
  await expect(page.locator('.panel-fault:visible'), `${what}: a panel met an error`).toHaveCount(0);
}

test(`the lecture page, 300 seeded presses (seed ${SEED})`, async ({ page }) => {
  test.setTimeout(240_000);
  await openLab(page, './');
  await page.locator('h1').first().click(); // the keys start from the page, as a reader's would
  const values = () => page.evaluate(() => JSON.stringify(Object.values(window.fresnelLab.hosts).map((h) => h.values)));
  const before = await values();
  const pressed = await fuzz(page, SEED, 300);
  await expectSound(page, `lecture page after ${pressed.join(' ')}`);
  expect(await values(), 'the presses reached the controls').not.toBe(before);
});

for (const [n, id] of PANEL_IDS.entries()) {
  test(`the ${id} embed, 50 seeded presses (seed ${SEED + n + 1})`, async ({ page }) => {
    await openLab(page, `embed.html?panel=${id}`);
    const pressed = await fuzz(page, SEED + n + 1, 50);
    await expectSound(page, `${id} after ${pressed.join(' ')}`);
  });
}

/** Presses `key` until focus is back on the element it started from; returns how many distinct elements it met. */
async function goRound(page, key, limit) {
  const seen = new Set();
  const mark = () => page.evaluate(() => {
    const e = /** @type {HTMLElement | null} */ (document.activeElement);
    if (!e || e === document.body) return 'body';
    e.dataset.roundId ??= String(document.querySelectorAll('[data-round-id]').length);
    return e.dataset.roundId;
  });
  const first = await mark();
  for (let i = 0; i < limit; i += 1) {
    await page.keyboard.press(key);
    const now = await mark();
    if (now === first) return seen.size;
    seen.add(now);
  }
  throw new Error(`${key} never came back round after ${limit} presses (stuck among ${seen.size})`);
}

test('focus is never trapped: Tab and Shift+Tab go all the way round the lecture page and an embed with an editor', async ({ page }) => {
  test.setTimeout(240_000);
  await openLab(page, './');
  await page.locator('h1').first().click();
  await page.keyboard.press('Tab');
  const forward = await goRound(page, 'Tab', 600);
  const back = await goRound(page, 'Shift+Tab', 600);
  expect(forward).toBeGreaterThan(PANEL_IDS.length); // panels mount as Tab brings them near: at least a stop in each
  expect(back).toBeGreaterThan(PANEL_IDS.length);
  await openLab(page, 'embed.html?panel=shader-lab');
  await page.locator('.cm-content').focus();
  await page.keyboard.press('Tab');
  expect(await page.evaluate(() => Boolean(document.activeElement?.closest('.cm-content')))).toBe(false);
  expect(await goRound(page, 'Tab', 200)).toBeGreaterThan(5);
});

test('with reduced motion nothing moves by itself: no panel keeps drawing, no CSS animation runs', async ({ page }) => {
  test.setTimeout(180_000);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  await openLab(page, './');
  for (const section of await page.locator('section[data-panel]').all()) {
    await section.scrollIntoViewIfNeeded();
    const id = await section.getAttribute('data-panel');
    await expect.poll(() => page.evaluate((panelId) => window.fresnelLab.hosts[panelId].mounted, id)).toBe(true);
    await settledFrames(page, id); // throws if it keeps drawing
  }
  expect(await page.evaluate(() => window.fresnelLab.hosts['refraction-waves'].values.play)).toBe(false);
  expect(await page.evaluate(() => document.getAnimations().length)).toBe(0);
});
