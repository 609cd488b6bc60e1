// Links, for every panel of the manifest: a link with a bad value for every key (seeded from a corpus
// of what breaks parsers, markup included) names each in a notice and takes every default, shows no
// NaN and makes no element, and the panel still follows a valid change of every key; the keys of older links still read, on the lecture page
// too. Each panel's section on the lecture page is checked in a11y.spec.js, the contract itself on
// each embed in embeds.spec.js.
import { test, expect, openLab } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';
import { probeValue } from './panelContract.js';
import { SEED, expectSound } from './keyFuzz.js';
import { injected, randomQuery } from './doorFuzz.js';

const schemas = Object.fromEntries(await Promise.all(PANELS.map(async ({ id }) => [id, (await import(`../../src/panels/${id}/schema.js`)).schema])));

/** Each key's aliases, grouped so that one link carries at most one alias of any key. */
function aliasLinks(schema) {
  const links = [];
  for (const [name, spec] of Object.entries(schema)) {
    (spec.aliases ?? []).forEach((alias, i) => {
      links[i] ??= [];
      links[i].push([alias, name, probeValue(spec)]);
    });
  }
  return links;
}

for (const [n, entry] of PANELS.entries()) {
  const { id } = entry;
  const schema = schemas[id];
  const still = `${entry.animates ? `&${entry.animates}=false` : ''}${id === 'normal-mips' ? '&truth=false' : ''}`;

  test(`${id}: a link of bad values gives a notice and the defaults, no markup, and the panel still follows; older keys still read`, async ({ page }) => {
    // Every key with a value from the corpus that its type refuses, and names every object inherits
    // (seeded: FUZZ_SEED replays it).
    // (The keys that hold an animated panel still are bad here too: it animates until the valid set.)
    const query = new URLSearchParams(randomQuery(SEED + 2000 + n, schema));
    await openLab(page, `./embed.html?panel=${id}&${query}`);
    const what = `${id} after the link ?${query}`.slice(0, 600);
    // Each key named in a notice, with the default it takes instead, and every value the default.
    await expect(page.locator('.notice').first()).toBeVisible();
    const lines = await page.locator('.notice li').allTextContents();
    for (const key of Object.keys(schema)) {
      expect(lines.some((line) => line.startsWith(`${key}=`) && line.includes('; using ')), `${what}: ${key} in a notice`).toBe(true);
    }
    expect(await page.evaluate((i) => ({ ...window.fresnelLab.hosts[i].values }), id), what)
      .toEqual(Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, spec.default])));
    await expectSound(page, what, { quoting: true });
    expect(await injected(page), 'markup in the link became elements').toEqual([]);
    // Then it follows a valid set of every key (a text, the shader lab's code, is set in embeds.spec.js).
    const update = Object.fromEntries(Object.entries(schema).filter(([, spec]) => spec.type !== 'text').map(([key, spec]) => [key, probeValue(spec)]));
    expect((await page.evaluate(([i, u]) => window.fresnelLab.hosts[i].set(u), [id, update])).rejected, 'refused a valid set').toEqual([]);
    expect(await page.evaluate(([i, keys]) => keys.map((k) => window.fresnelLab.hosts[i].values[k]), [id, Object.keys(update)]), 'follows a valid set')
      .toEqual(Object.values(update));

    for (const link of aliasLinks(schema)) {
      await openLab(page, `./embed.html?panel=${id}${still}&${link.map(([alias, , v]) => `${alias}=${encodeURIComponent(v)}`).join('&')}`);
      for (const [alias, name, v] of link) {
        expect(await page.evaluate(([i, k]) => window.fresnelLab.hosts[i].values[k], [id, name]), `${alias} reads as ${name}`).toEqual(v);
      }
      await expect(page.locator('.notice')).toHaveCount(0);
    }
  });
}

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
