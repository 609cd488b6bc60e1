// Keyboard only, at random but reproducibly: seeded presses of Tab, Shift+Tab, the arrows, the Page
// keys, Home, End, Space, Enter and the digits, and what must hold after them: no NaN or
// "undefined" on screen or in an accessible name, no panel failed, and every value inside its
// schema (checked here, not by the page's own code). FUZZ_SEED=<n> replays a run.
import { expect } from './fixtures.js';
import { seededRandom } from '../../src/homework/seededRandom.js';

export const SEED = Number(process.env.FUZZ_SEED ?? 20261203);
const KEYS = ['Tab', 'Tab', 'Tab', 'Shift+Tab', 'ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'PageUp', 'PageDown',
  'Home', 'End', ' ', 'Enter', '0', '1', '2', '3', '4', '5', '6', '7', '8', '9'];

// Words the page means: prose about NaN, the stability map's class, an exercise's criterion.
const MEANT = [/returns NaN/g, /NaN or infinite/g, /\(no NaN[^)]*\)/g, /NaN\/∞/g];

/** Text on screen and in accessible names and values (less the notices when they quote outside input). */
const shownText = (page, quoting) => page.evaluate((skipNotices) => {
  const named = [...document.querySelectorAll('[aria-label], [aria-valuetext], [aria-valuenow], [title]')]
    .map((e) => ['aria-label', 'aria-valuetext', 'aria-valuenow', 'title'].map((a) => e.getAttribute(a) ?? '').join(' '));
  const descriptions = [...document.querySelectorAll('.panel-description, [id$="-description"]')].map((e) => e.textContent);
  let body = document.body.innerText;
  if (skipNotices) for (const notice of document.querySelectorAll('.notice')) body = body.replace(notice.innerText, '');
  return [body, ...named, ...descriptions].join('\n');
}, quoting);

/** Every host's values checked against its schema, here and not by the page's own code. */
export const outsideSchema = (page) => page.evaluate(() => {
  const bad = [];
  for (const [id, host] of Object.entries(window.fresnelLab.hosts)) {
    for (const [key, spec] of Object.entries(host.panel.schema)) {
      const v = host.values[key];
      const options = Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options ?? {});
      const ok = spec.type === 'number' ? Number.isFinite(v) && v >= spec.min && v <= spec.max && (!spec.integer || Number.isInteger(v))
        : spec.type === 'enum' ? options.includes(String(v))
          : spec.type === 'color' ? /^#[0-9a-f]{6}$/.test(v)
            : spec.type === 'boolean' ? typeof v === 'boolean'
              : typeof v === 'string' && (spec.maxLength === undefined || v.length <= spec.maxLength);
      if (!ok) bad.push(`${id}.${key} = ${JSON.stringify(v)}`);
    }
    for (const key of Object.keys(host.values)) if (!Object.hasOwn(host.panel.schema, key)) bad.push(`${id}.${key} is not in the schema`);
  }
  return bad;
});

/** Presses `presses` seeded keys from wherever the focus is; returns them. */
export async function fuzzKeys(page, seed, presses) {
  const { next } = seededRandom(seed);
  const pressed = [];
  for (let i = 0; i < presses; i += 1) {
    let key = KEYS[Math.floor(next() * KEYS.length)];
    // A link would leave the page under test; Tab past it instead (asked only for the keys that follow one).
    if ((key === 'Enter' || key === ' ') && await page.evaluate(() => Boolean(document.activeElement?.closest('a[href]')))) key = 'Tab';
    pressed.push(key);
    await page.keyboard.press(key);
  }
  return pressed;
}

/**
 * No NaN or undefined shown or named, every value in its schema, no panel failed or met an error.
 * quoting: the page's notices quote what a link said (which may be "NaN"), so they are not read.
 */
export async function expectSound(page, what, { quoting = false } = {}) {
  let text = await shownText(page, quoting);
  for (const meant of MEANT) text = text.replace(meant, '');
  expect(text.match(/.{0,40}\b(NaN|undefined)\b.{0,40}/g), `${what}: NaN or undefined shown`).toBeNull();
  expect(await outsideSchema(page), `${what}: values outside their schema`).toEqual([]);
  await expect(page.locator('.notice-error'), `${what}: a panel failed`).toHaveCount(0);
  await expect(page.locator('.panel-fault:visible'), `${what}: a panel met an error`).toHaveCount(0);
}
