// The panel contract (src/host/panelContract.js), checked once for every panel of the manifest:
// it mounts in embed.html and on the lecture page, describes itself in numbers, exports what it
// declares, draws nothing while nothing changes, gives its WebGL context back when disposed, comes
// back with its values when remounted, treats a bad link value with a notice and the default,
// reads the keys of older links, and cannot write its values itself.
import { test, expect, openLab, expectIdle, settledFrames } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';
import { stepDecimals } from '../../src/host/params.js';

/** The first parameter, a value for it other than the default, and how the link writes it. */
function probeValue(spec) {
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
const schemaOf = (page, id) => page.evaluate((i) => JSON.parse(JSON.stringify(window.fresnelLab.hosts[i].panel.schema)), id);

for (const entry of PANELS) {
  const { id } = entry;
  // An animated panel is checked with its animation off: then it, too, draws only on change.
  const still = entry.animates ? `&${entry.animates}=false` : '';

  test(`${id}: the embed keeps the panel contract`, async ({ page }) => {
    test.setTimeout(120_000);
    await openLab(page, `./embed.html?panel=${id}${still}`);
    await expect(page.locator('.embed-title')).toHaveText(entry.title.replace(/_([a-z])/g, '$1')); // n_t as n with subscript t
    await expect(page).toHaveTitle(`Fresnel Lab: ${entry.title}`);
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
    const control = page.locator('.lil-controller', { hasText: schema[key].label }).first();
    if (schema[key].type === 'number') {
      expect(Number(await control.locator('input').first().inputValue())).toBeCloseTo(value, 6);
    } else if (schema[key].type === 'enum') {
      const label = Array.isArray(schema[key].options) ? String(value) : schema[key].options[value];
      await expect(control.locator('.lil-display')).toHaveText(label);
    }
  });

  test(`${id}: a bad link value gives a notice and the default; older keys still read`, async ({ page }) => {
    await openLab(page, `./embed.html?panel=${id}${still}`);
    const schema = await schemaOf(page, id);
    const [key] = Object.keys(schema);
    await openLab(page, `./embed.html?panel=${id}${still}&${key}=%3Cbad%3E`);
    await expect(page.locator('.notice')).toContainText(`${key}=<bad>`);
    await expect(page.locator('.notice')).toContainText('using');
    expect(await page.evaluate(([i, k]) => window.fresnelLab.hosts[i].values[k], [id, key])).toEqual(schema[key].default);

    for (const [name, spec] of Object.entries(schema)) {
      for (const alias of spec.aliases ?? []) {
        const value = probeValue(spec);
        await openLab(page, `./embed.html?panel=${id}${still}&${alias}=${encodeURIComponent(value)}`);
        expect(await page.evaluate(([i, k]) => window.fresnelLab.hosts[i].values[k], [id, name]), `${alias} reads as ${name}`)
          .toEqual(value);
        await expect(page.locator('.notice')).toHaveCount(0);
      }
    }
  });
}

test('every panel of the manifest has its section on the lecture page, and mounts there', async ({ page }) => {
  test.setTimeout(180_000);
  await openLab(page);
  const sections = await page.evaluate(() => [...document.querySelectorAll('section[data-panel]')].map((s) => ({
    id: s.dataset.panel, heading: s.querySelector('h2').textContent, lede: s.querySelector('.lede').textContent,
  })));
  expect(sections.map((s) => s.id)).toEqual(PANELS.map((p) => p.id));
  await expect(page.locator('main > .notice-error')).toHaveCount(0);
  for (const [i, entry] of PANELS.entries()) {
    expect(sections[i].heading.replace(/\s+/g, ' ')).toBe(entry.title.replace(/_([a-z])/g, '$1'));
    expect(sections[i].lede).toContain('(');
    await page.locator(`section[data-panel="${entry.id}"]`).scrollIntoViewIfNeeded();
    await expect.poll(() => page.evaluate((pid) => window.fresnelLab.hosts[pid].mounted, entry.id), { message: entry.id }).toBe(true);
    await expect(page.locator(`section[data-panel="${entry.id}"] .panel-description`)).toHaveText(/\d/);
  }
});

test('links made with the old index keys open the same view on the lecture page', async ({ page }) => {
  // n1/n2 and n were the keys of these panels before the lecture's n_i/n_t became the one notation.
  await openLab(page, './?angle-ratio.n1=1.5&angle-ratio.n2=1.2&metals.n=2.4&reflect-refract.n=1.5&polarization.n2=1.8#angle-ratio');
  const values = await page.evaluate(() => Object.fromEntries(['angle-ratio', 'metals', 'reflect-refract', 'polarization']
    .map((pid) => [pid, { ...window.fresnelLab.hosts[pid].values }])));
  expect(values['angle-ratio']).toMatchObject({ nI: 1.5, nT: 1.2 });
  expect(values.metals.nT).toBe(2.4);
  expect(values['reflect-refract'].nT).toBe(1.5);
  expect(values.polarization.nT).toBe(1.8);
  await expect(page.locator('.notice')).toHaveCount(0);
  // The next change writes the link in the new keys.
  await page.evaluate(() => window.fresnelLab.hosts['angle-ratio'].set({ theta: 30 }));
  await expect(page).toHaveURL(/angle-ratio\.nI=1\.5/);
  await expect(page).toHaveURL(/angle-ratio\.nT=1\.2/);
  await expect(page).not.toHaveURL(/angle-ratio\.n[12]=/);
});
