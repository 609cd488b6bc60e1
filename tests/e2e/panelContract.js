// The panel contract (src/host/panelContract.js), checked on a panel's embed once it is open: it
// describes itself in numbers, exports what it declares, draws nothing while nothing changes, follows
// a change made through its host, cannot write its values itself, gives its WebGL context back when
// disposed and comes back with its values when remounted.
import { expect, expectIdle, settledFrames } from './fixtures.js';
import { stepDecimals } from '../../src/host/params.js';
import { english } from './englishText.js';

/** The first parameter, a value for it other than the default, and how the link writes it. */
export function probeValue(spec) {
  if (spec.type === 'number') {
    const decimals = stepDecimals(spec.step);
    const steps = Math.round((0.37 * (spec.max - spec.min)) / spec.step);
    const value = Number((spec.min + steps * spec.step).toFixed(decimals));
    return value === spec.default ? Number((value + spec.step).toFixed(decimals)) : value;
  }
  if (spec.type === 'enum') {
    const values = Array.isArray(spec.options) ? spec.options : Object.keys(spec.options);
    return values[(values.indexOf(spec.default) + 1) % values.length];
  }
  if (spec.type === 'boolean') return !spec.default;
  return spec.default === '#123456' ? '#654321' : '#123456';
}

/** The panel's schema as the page has it (specs are plain data). */
export const schemaOf = (page, id) => page.evaluate((i) => JSON.parse(JSON.stringify(window.fresnelLab.hosts[i].panel.schema)), id);

/**
 * The contract, on the embed of manifest `entry` already open in `page`; `words`: the English
 * catalogue that page was built from (a copy of the project has its own).
 */
export async function expectPanelContract(page, entry, words = english) {
  const { id } = entry;
  const title = words.panels[`${id}.title`];
  await expect(page.locator('.embed-title')).toHaveText(title.replace(/_([a-z])/g, '$1')); // n_t as n with subscript t
  await expect(page).toHaveTitle(`Fresnel Lab: ${title}`);
  const host = (fn, arg) => page.evaluate(fn, [id, arg]);
  expect(await host(([i]) => window.fresnelLab.hosts[i].mounted)).toBe(true);

  // describe(): the key numbers in words, shown under the panel and linked from every canvas.
  const description = page.locator('.panel-description');
  await expect(description).toHaveText(/\d/);
  expect(await host(() => [...document.querySelectorAll('.panel-content canvas')]
    .every((c) => c.getAttribute('aria-describedby') === document.querySelector('.panel-description').id))).toBe(true);

  // csv() and png() where declared, and the toolbar offers exactly those.
  const declared = await host(([i]) => {
    const p = window.fresnelLab.panels[i];
    return { csv: typeof p.csv === 'function', png: typeof p.png === 'function' };
  });
  await expect(page.locator('.toolbar button', { hasText: 'Export CSV' })).toBeEnabled({ enabled: declared.csv });
  await expect(page.locator('.toolbar button', { hasText: 'Export PNG' })).toBeEnabled({ enabled: declared.png });
  if (declared.csv) {
    const table = await host(([i]) => {
      const { filename, columns } = window.fresnelLab.panels[i].csv();
      const lengths = Object.values(columns).map((c) => c.length);
      const cells = Object.values(columns).flat();
      return { filename, names: Object.keys(columns), lengths, typed: cells.every((v) => typeof v === 'number' || typeof v === 'string') };
    });
    expect(table.names.length).toBeGreaterThan(0);
    expect(new Set(table.lengths).size).toBe(1);
    expect(table.typed).toBe(true);
    if (table.filename !== undefined) expect(table.filename).toMatch(/\.csv$/);
  }
  if (declared.png) {
    await expect.poll(() => host(([i]) => window.fresnelLab.panels[i].png()?.slice(0, 22) ?? null))
      .toBe('data:image/png;base64,');
  }

  // Nothing draws while nothing changes (the window below is the time in which nothing may draw).
  const frames = () => host(([i]) => window.fresnelLab.hosts[i].frames);
  const idle = await expectIdle(page, id);

  // A change goes through the host: the picture follows, and the description is the new one.
  const schema = await schemaOf(page, id);
  const [key] = Object.keys(schema);
  const value = probeValue(schema[key]);
  const result = await host(([i, update]) => window.fresnelLab.hosts[i].set(update), { [key]: value });
  expect(result.rejected).toEqual([]);
  expect(result.changed).toContain(key);
  await expect.poll(frames, { message: 'a change draws (a panel without WebGL counts its redraw)' }).toBeGreaterThan(idle);
  // Once it has settled, the description shown is the panel's own for the new value.
  await settledFrames(page, id);
  await expect.poll(async () => (await description.textContent()) === await host(([i]) => window.fresnelLab.panels[i].describe()),
    { message: 'the description follows the change' }).toBe(true);

  // Panels cannot write their values: the host owns them.
  const write = await host(([i, k]) => {
    try {
      window.fresnelLab.hosts[i].values[k] = 0;
      return 'written';
    } catch (error) {
      return error.name;
    }
  }, key);
  expect(write).toBe('TypeError');

  // Disposed, it gives its WebGL context back; remounted, it comes back as it was.
  const valuesBefore = await host(([i]) => ({ ...window.fresnelLab.hosts[i].values }));
  await host(([i]) => window.fresnelLab.hosts[i].unmount());
  expect(await host(() => window.fresnelLab.contexts.live), 'live WebGL contexts after dispose').toBe(0);
  await host(([i]) => { window.fresnelLab.hosts[i].mount(); });
  expect(await host(([i]) => ({ ...window.fresnelLab.hosts[i].values }))).toEqual(valuesBefore);
  if (entry.webgl) expect(await host(() => window.fresnelLab.contexts.live)).toBeGreaterThan(0);
  await expect(description).toHaveText(/\d/);
  const control = page.locator('.lil-controller', { hasText: words.controls[`${id}.${key}`] }).first();
  if (schema[key].type === 'number') {
    expect(Number(await control.locator('input').first().inputValue())).toBeCloseTo(value, 6);
  } else if (schema[key].type === 'enum') {
    const label = words.controls[`${id}.${key}.${value}`] ?? String(value);
    await expect(control.locator('.lil-display')).toHaveText(label);
  }
}
