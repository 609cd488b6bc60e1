// Keyboard only, at random but reproducibly: seeded presses of Tab, Shift+Tab, the arrows, the Page
// keys, Home, End, Space, Enter and the digits, and what must hold after them: no NaN or
// "undefined" on screen or in an accessible name, no panel failed, every value inside its schema
// (checked here, not by the page's own code), and that the keys reached a control of the panel.
// FUZZ_SEED=<n> replays a run.
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

// A panel's own keyboard-operable controls: its form fields, sliders and focusable canvases, not
// the toolbar's export buttons or a notice's Dismiss.
const CONTROL = 'input, select, textarea, button, [role="slider"], [role="spinbutton"], [contenteditable="true"], [tabindex]:not([tabindex="-1"])';
const PANEL_PART = '.panel-side, .panel-content';
const NOT_PANEL = '.toolbar, .notice';

/**
 * Puts the focus on the first control of the panel (an embed's), as a reader's click into it would:
 * from the page's start a seed with few Tabs may stay in the toolbar, and test nothing of the panel.
 */
export async function focusPanel(page) {
  await page.locator(`:is(${PANEL_PART}) :is(${CONTROL}):not(:is(${NOT_PANEL}) *):visible`).first().focus();
}

/**
 * Presses `presses` seeded keys from wherever the focus is; returns them. What they reach is
 * recorded in the page for expectKeysReached: the first control of a panel they moved focus to,
 * and how many presses changed a host's value.
 */
export async function fuzzKeys(page, seed, presses) {
  await page.evaluate(([control, part, not]) => {
    const values = () => JSON.stringify(Object.values(window.fresnelLab.hosts).map((h) => h.values));
    const reached = { control: null, changes: 0, last: values() };
    if (!window.__keysReached) {
      document.addEventListener('focusin', ({ target }) => {
        const seen = window.__keysReached;
        if (!seen.control && target.matches?.(control) && target.closest(part) && !target.closest(not)) {
          seen.control = target.getAttribute('aria-label') ?? target.closest('.lil-controller')?.textContent.trim() ?? target.tagName;
        }
      }, true);
      // After each key's own handlers: a value changed by that press (or by one just before it).
      document.addEventListener('keyup', () => {
        const seen = window.__keysReached;
        const now = values();
        if (now !== seen.last) Object.assign(seen, { changes: seen.changes + 1, last: now });
      }, true);
    }
    window.__keysReached = reached;
  }, [CONTROL, PANEL_PART, NOT_PANEL]);
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
 * The panels on the page have keyboard-operable controls, and the presses since fuzzKeys reached
 * one: they moved focus onto one or changed a value (keys that never leave the page's chrome, or
 * that a handler swallows, test nothing of the panel).
 */
export async function expectKeysReached(page, what) {
  const { operable, control, changes } = await page.evaluate(([c, part, not]) => ({
    operable: [...document.querySelectorAll(`:is(${part}) :is(${c})`)].filter((e) => !e.closest(not) && !e.disabled && e.checkVisibility()).length,
    control: window.__keysReached.control,
    changes: window.__keysReached.changes + (JSON.stringify(Object.values(window.fresnelLab.hosts).map((h) => h.values)) !== window.__keysReached.last),
  }), [CONTROL, PANEL_PART, NOT_PANEL]);
  expect(operable, `${what}: controls a key can reach`).toBeGreaterThan(0);
  expect({ control, changes }, `${what}: no key reached a control`).not.toEqual({ control: null, changes: 0 });
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
