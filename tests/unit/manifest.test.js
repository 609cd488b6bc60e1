import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { dirname, join, normalize, relative, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import {
  PANELS, PANEL_IDS, PLACES_MARKER, lecturePrefix, manifestProblems, panelTextFrom, placesCss, sectionHtml,
} from '../../src/panels/manifest.js';
import { formatValue, parseValue, readParams } from '../../src/host/params.js';
import { FIXED_PANEL_IDS } from './fixedPanelIds.js';

const root = resolve(import.meta.dirname, '../..');
const files = readdirSync(resolve(root, 'src/panels'), { withFileTypes: true }).filter((d) => d.isDirectory())
  .flatMap((d) => ['index.js', 'schema.js'].filter((f) => existsSync(resolve(root, 'src/panels', d.name, f))).map((f) => `${d.name}/${f}`));
const indexHtml = readFileSync(resolve(root, 'index.html'), 'utf8');
const catalogue = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8'));
const words = catalogue.panels;
const { controls } = catalogue;
const modules = Object.fromEntries(await Promise.all(PANEL_IDS.map(async (id) => [id, await import(`../../src/panels/${id}/index.js`)])));
const schemas = Object.fromEntries(await Promise.all(PANEL_IDS.map(async (id) => [id, (await import(`../../src/panels/${id}/schema.js`)).schema])));

/** The modules a panel's index.js reaches through relative imports (static, dynamic, workers), as repository paths. */
function reachedFrom(start) {
  const seen = new Set();
  for (const todo = [start]; todo.length;) {
    const path = todo.pop();
    if (seen.has(path)) continue;
    seen.add(path);
    const text = readFileSync(resolve(root, path), 'utf8');
    for (const [, spec] of text.matchAll(/(?:from|import\s*\(|new URL\()\s*['"](\.{1,2}\/[^'"?]+\.js)['"?]/g)) {
      todo.push(relative(root, normalize(join(root, dirname(path), spec))).replaceAll('\\', '/'));
    }
  }
  return seen;
}
// Every counted WebGL context is opened by a module that calls countContext (src/gl/contextBudget.js).
const OPENS_CONTEXT = /\bcountContext\(/;

describe('the panel manifest', () => {
  it('agrees with the panel folders and the lecture page', () => {
    expect(manifestProblems(files, words, indexHtml)).toEqual([]);
  });
  it('names what is wrong: a missing module or schema, a stray folder, a hand-written section', () => {
    const problems = manifestProblems([...files.filter((f) => f !== 'metals/index.js' && f !== 'schlick/schema.js'), 'stray/index.js'],
      words, indexHtml.replace('<main>', '<main><section data-panel="metals"></section>'));
    expect(problems).toEqual([
      'The panel “schlick” has no src/panels/schlick/schema.js: its parameters (export const schema) come with the page, apart from its module.',
      'The panel “metals” has no module src/panels/metals/index.js.',
      'src/panels/stray/ (index.js) is not in the manifest.',
      'index.html has a hand-written section “metals”: sections come from the manifest.',
    ]);
    expect(manifestProblems(files, words, '<main></main>')).toEqual(['index.html has no place for the panel sections.']);
    // A panel's words come from the catalogue: one without its lede there is named.
    const without = Object.fromEntries(Object.entries(words).filter(([key]) => key !== 'asphalt.lede'));
    expect(manifestProblems(files, without)).toEqual(['The panel “asphalt” has no lede (“asphalt.lede” in locales/en.json, namespace "panels").']);
  });
  it('names a place the entry does not give', () => {
    const { place, ...entry } = PANELS[0];
    expect(manifestProblems(files.filter((f) => f.startsWith(`${entry.id}/`)), words, undefined, [{ ...entry, place: { ...place, wide: undefined } }]))
      .toEqual([
      `The panel “${entry.id}” has no place.wide: the height in px the lecture page keeps for it before it mounts (docs/panels.md).`,
    ]);
    expect(manifestProblems(files.filter((f) => f.startsWith(`${entry.id}/`)), words, undefined, [entry])).toHaveLength(3);
  });
  it('names a webglAtTimes that is not true, or that comes with webgl true', () => {
    const entry = PANELS.find((p) => p.id === 'schlick');
    const own = files.filter((f) => f.startsWith('schlick/'));
    const problems = (more) => manifestProblems(own, words, undefined, [{ ...entry, ...more }]);
    expect(problems({ webglAtTimes: true })).toEqual([]);
    expect(problems({ webglAtTimes: 'yes' })).toEqual(['The panel “schlick” has webglAtTimes yes: true or left out, and only with webgl false.']);
    expect(problems({ webgl: true, webglAtTimes: true })).toEqual([
      'The panel “schlick” has webglAtTimes true: true or left out, and only with webgl false.',
    ]);
  });
  it('keeps every id that links and embeds already use', () => {
    // Renaming or removing an id breaks every link and embed made with it; a new panel adds one.
    expect(PANEL_IDS).toEqual(expect.arrayContaining([...FIXED_PANEL_IDS]));
  });
  it('writes the place of each panel for each layout, narrowest first, so that a wider layout overrides it', () => {
    const [narrow, wide, widest, ...more] = placesCss().split('@media ');
    expect(more).toEqual([]);
    expect([wide, widest].map((block) => block.slice(0, block.indexOf(' {')))).toEqual(['(min-width: 1001px)', '(min-width: 1450px)']);
    for (const { id, place } of PANELS) {
      const rule = (px) => `#${id} > .panel-mount { min-height: ${px}px; }`;
      expect(narrow).toContain(rule(place.narrow));
      expect(wide).toContain(rule(place.wide));
      expect(widest).toContain(rule(place.widest));
    }
    expect(readFileSync(resolve(root, 'src/panelPlaces.css'), 'utf8')).toContain(PLACES_MARKER);
  });
  it('the hero owns the short URL keys; other panels prefix theirs', () => {
    expect(PANELS.filter((p) => p.hero).map((p) => p.id)).toEqual(['spheres']);
    expect(lecturePrefix('spheres')).toBe('');
    expect(lecturePrefix('metals')).toBe('metals.');
  });
  it('writes each section with its id, heading, lede and citation', () => {
    const html = sectionHtml(PANELS.find((p) => p.id === 'r0-derivation'), panelTextFrom(words, 'r0-derivation'));
    expect(html).toContain('data-panel="r0-derivation"');
    expect(html).toContain('aria-labelledby="r0-derivation-title"');
    expect(html).toContain('n<sub>t</sub>');
    expect(html).toContain('<span class="cite">(Lecture: “Reflection Math”, R(0°).)</span>');
    expect(html).toContain('<div class="panel-mount"></div>');
  });
});

describe.each(PANEL_IDS)('the %s module', (id) => {
  const entry = PANELS.find((p) => p.id === id);
  const module = modules[id];
  it('exports schema and mount, and leaves id, title and traits to the manifest', () => {
    expect(typeof module.mount).toBe('function');
    expect(module.schema).toBeTypeOf('object');
    expect(module.schema, 'the schema of its schema.js (the loader refuses another)').toBe(schemas[id]);
    for (const name of ['id', 'title', 'usesWebGL', 'materialParam', 'materialSelectParam']) expect(module[name]).toBeUndefined();
  });
  it('has a schema whose defaults are valid values with labels', () => {
    const keys = new Set(Object.keys(module.schema));
    for (const [key, spec] of Object.entries(module.schema)) {
      // The control's name is the catalogue's (controls namespace), and every option that is a word has one.
      expect(controls[`${id}.${key}`], `${id}.${key} has a name in locales/en.json`).toBeTruthy();
      expect(spec.label, `${id}.${key}: names are in the catalogue, not the schema`).toBeUndefined();
      if (spec.type === 'enum') expect(Array.isArray(spec.options), `${id}.${key} options are ids`).toBe(true);
      expect(parseValue(spec, spec.default), `${id}.${key} default`).toEqual({ ok: true, value: spec.default });
      for (const alias of spec.aliases ?? []) expect(keys.has(alias), `${id}: alias ${alias} is also a key`).toBe(false);
    }
  });
  it('a link that states every default, keyed as on the lecture page, reads back as the defaults', () => {
    // Written as a link writes it (a number to its step's decimals) and read as a link is read:
    // a default its own text does not read back would be refused or moved by every link that says it.
    const prefix = lecturePrefix(id);
    const specs = Object.entries(module.schema);
    const link = new URLSearchParams(specs.map(([key, spec]) => [prefix + key, formatValue(spec, spec.default)]));
    const { values, problems } = readParams(module.schema, link, prefix);
    expect(problems).toEqual([]);
    for (const [key, spec] of specs) {
      // (stability's tolerance defaults to the exact half step, 0.00445475…, off its 1e-7 grid.)
      if (spec.type === 'number') expect(Math.abs(values[key] - spec.default), `${id}.${key}`).toBeLessThanOrEqual(spec.step / 2);
      else expect(values[key], `${id}.${key}`).toBe(spec.default);
    }
  });
  it('says whether it holds a WebGL context, always (webgl) or at times (webglAtTimes), as its code does', () => {
    const opens = [...reachedFrom(`src/panels/${id}/index.js`)]
      .filter((path) => !path.endsWith('contextBudget.js') && OPENS_CONTEXT.test(readFileSync(resolve(root, path), 'utf8')));
    // A panel that never opens one says neither; one that does says one of them (a deck preloads neither).
    expect(entry.webgl || entry.webglAtTimes === true, `${id} reaches ${opens.join(', ') || 'no module that opens a context'}`)
      .toBe(opens.length > 0);
  });
  it('takes the page-wide material through a parameter it has', () => {
    if (entry.material) {
      expect(module.schema[entry.material]?.type).toBe('number');
      expect(entry.material).toBe('nT'); // one notation: the material sets n_t everywhere
    }
    if (entry.materialSelect) expect(module.schema[entry.materialSelect]?.type).toBe('enum');
    if (entry.animates) expect(module.schema[entry.animates]?.type).toBe('boolean');
  });
  it('labels its indices in the lecture notation, n_i and n_t', () => {
    for (const key of ['nI', 'nT']) {
      if (module.schema[key]) expect(controls[`${id}.${key}`]).toMatch(key === 'nI' ? /^n_i\b/ : /^n_t\b/);
    }
    for (const key of Object.keys(module.schema)) expect(controls[`${id}.${key}`]).not.toMatch(/n₁|n₂|θ₁|θ₂/);
  });
});
