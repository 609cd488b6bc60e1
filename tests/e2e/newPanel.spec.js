// Adding a panel takes its folder, its manifest entry and its words, nothing else (docs/panels.md).
// The smallest panel of docs/panels.md is added that way to a copy of the project: without its
// schema.js or without a place in its entry the build stops and names which; with both the copy
// type-checks and builds as `npm run build` does, the unit tests that read the manifest pass
// there, the lecture page keeps the panel's place from its entry in each layout, and its embed
// keeps the panel contract; `npm run panel-list` writes its row of the docs' list of panels, as
// docs/panels.md says. A panel that needed more (a CSS rule, a line of the docs by hand, a test's list of
// ids, a homework question) fails here. 40–90 s on two cores, most of it the copy's type check,
// builds and unit tests.
import { readdirSync, readFileSync, renameSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { preview } from 'vite';
import { test, expect, openLab } from './fixtures.js';
import { expectPanelContract } from './panelContract.js';
import { mountedHeight, reservedHeight } from './layout.js';
import { docsPanel, editFile, removeCopy, runIn, scaffold } from './scaffold.js';
import { panelListFiles } from '../../scripts/panelListFiles.js';

const panel = docsPanel();
const VITE = 'node_modules/vite/bin/vite.js';
/** A window width in each layout of a place (PLACE_LAYOUTS in the manifest). */
const WIDTHS = { narrow: 800, wide: 1280, widest: 1920 };

test.describe.configure({ mode: 'serial' });
let dir;
let server;

test.beforeAll(() => { dir = scaffold(panel); });
test.afterAll(async () => {
  await server?.close();
  if (dir) removeCopy(dir);
});

/** The copy's manifest entry of the new panel, as its build read it. */
const entryOf = async () => (await import(pathToFileURL(join(dir, 'src/panels/manifest.js')).href)).panelEntry(panel.id);

test('docs/panels.md gives the smallest panel whole: schema.js, index.js, an entry with its place, its words', () => {
  expect(Object.keys(panel.files).sort()).toEqual([`src/panels/${panel.id}/index.js`, `src/panels/${panel.id}/schema.js`]);
  expect(panel.entry).toMatch(/\bplace: \{/);
  expect(Object.keys(panel.words?.panels ?? {}).sort()).toEqual(['title', 'lede', 'cite'].map((f) => `${panel.id}.${f}`).sort());
});

test('without its schema.js, or with no place in its entry, the build stops and says which', async () => {
  test.setTimeout(120_000);
  const schema = join(dir, `src/panels/${panel.id}/schema.js`);
  renameSync(schema, `${schema}.away`);
  const noSchema = await runIn(dir, process.execPath, [VITE, 'build', '--logLevel', 'error']);
  renameSync(`${schema}.away`, schema);
  expect(noSchema.code).not.toBe(0);
  expect(noSchema.output).toContain(`The panel “${panel.id}” has no src/panels/${panel.id}/schema.js`);

  const manifest = 'src/panels/manifest.js';
  const withPlace = readFileSync(join(dir, manifest), 'utf8');
  editFile(dir, manifest, (text) => text.replace(panel.entry.trimEnd(), panel.entry.trimEnd().replace(/\n\s*place: \{[^}]*\},/, '')));
  const noPlace = await runIn(dir, process.execPath, [VITE, 'build', '--logLevel', 'error']);
  editFile(dir, manifest, () => withPlace);
  expect(noPlace.code).not.toBe(0);
  expect(noPlace.output).toContain(`The panel “${panel.id}” has no place.narrow`);
});

test('with its panel list written, the copy type-checks (the contract\'s types) and the unit tests that read the manifest pass', async () => {
  test.setTimeout(180_000);
  const list = await runIn(dir, 'npm', ['run', 'panel-list']);
  expect(list.code, list.output).toBe(0);
  const listed = panelListFiles(dir);
  expect(listed.length).toBeGreaterThan(0);
  for (const file of listed) expect(readFileSync(join(dir, file), 'utf8'), file).toContain(`| \`${panel.id}\` | no WebGL |`);
  const types = await runIn(dir, 'node_modules/.bin/tsc', ['-p', 'jsconfig.json']);
  expect(types.code, types.output).toBe(0);
  // Every unit test that reads the manifest, the loader or the schemas: none may want more of a panel.
  const units = readdirSync(join(dir, 'tests/unit')).filter((f) => f.endsWith('.test.js'))
    .filter((f) => /panels\/(manifest|loadPanel|panelSchema)\.js/.test(readFileSync(join(dir, 'tests/unit', f), 'utf8')));
  expect(units).toContain('manifest.test.js');
  const run = await runIn(dir, 'node_modules/.bin/vitest', ['run', ...units.map((f) => `tests/unit/${f}`)]);
  expect(run.code, run.output.slice(-4000)).toBe(0);
});

test.describe('with its folder and its entry alone, built as npm run build does', () => {
  test.beforeAll(async () => {
    test.setTimeout(300_000);
    const build = await runIn(dir, 'npm', ['run', 'build']);
    expect(build.code, build.output.slice(-4000)).toBe(0);
    server = await preview({ root: dir, configFile: join(dir, 'vite.config.js'), logLevel: 'silent', preview: { port: 0 } });
  });
  const url = () => `http://127.0.0.1:${server.httpServer.address().port}/`;

  test('the lecture page has the panel\'s section, keeps its place from its entry in each layout, and mounts it there', async ({ page }) => {
    test.setTimeout(180_000);
    const { place } = await entryOf();
    for (const [layout, width] of Object.entries(WIDTHS)) {
      await page.setViewportSize({ width, height: 800 });
      await openLab(page, url());
      await expect(page.locator('main > .notice-error')).toHaveCount(0);
      expect(await page.evaluate(() => [...document.querySelectorAll('section[data-panel]')].at(-1).id)).toBe(panel.id);
      expect(await page.evaluate((id) => window.fresnelLab.hosts[id].mounted, panel.id), 'not yet near').toBe(false);
      expect(await reservedHeight(page, panel.id), `${layout} at ${width} px`).toBe(place[layout]);
      await page.evaluate((id) => document.getElementById(id).scrollIntoView(), panel.id);
      await expect.poll(() => page.evaluate((id) => window.fresnelLab.hosts[id].mounted, panel.id)).toBe(true);
      const height = await mountedHeight(page, panel.id);
      expect(place[layout], `${layout} at ${width} px`).toBeLessThanOrEqual(height);
      expect(place[layout], `${layout} at ${width} px`).toBeGreaterThan(0.4 * height);
    }
  });

  test('its embed keeps the panel contract', async ({ page }) => {
    await openLab(page, `${url()}embed.html?panel=${panel.id}`);
    await expectPanelContract(page, await entryOf(), JSON.parse(readFileSync(join(dir, 'locales/en.json'), 'utf8')));
  });
});
