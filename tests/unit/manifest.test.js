import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { PANELS, PANEL_IDS, lecturePrefix, manifestProblems, sectionHtml } from '../../src/panels/manifest.js';
import { defaults, parseValue, readParams } from '../../src/host/params.js';

const root = resolve(import.meta.dirname, '../..');
const folders = readdirSync(resolve(root, 'src/panels'), { withFileTypes: true })
  .filter((d) => d.isDirectory() && existsSync(resolve(root, 'src/panels', d.name, 'index.js'))).map((d) => d.name);
const indexHtml = readFileSync(resolve(root, 'index.html'), 'utf8');
const modules = Object.fromEntries(await Promise.all(PANEL_IDS.map(async (id) => [id, await import(`../../src/panels/${id}/index.js`)])));

describe('the panel manifest', () => {
  it('agrees with the panel folders and the lecture page', () => {
    expect(manifestProblems(folders, indexHtml)).toEqual([]);
  });
  it('names what is wrong: a missing module, a stray folder, a hand-written section', () => {
    const problems = manifestProblems([...folders.filter((f) => f !== 'metals'), 'stray'],
      indexHtml.replace('<main>', '<main><section data-panel="metals"></section>'));
    expect(problems).toEqual(expect.arrayContaining([
      expect.stringContaining('“metals” has no module'),
      expect.stringContaining('src/panels/stray/index.js is not in the manifest'),
      expect.stringContaining('hand-written section “metals”'),
    ]));
    expect(manifestProblems(folders, '<main></main>')).toEqual(['index.html has no place for the panel sections.']);
  });
  it('keeps the fixed ids that links and embeds already use, in lecture order', () => {
    // Renaming an id breaks every link and embed made with it: change this list only with aliases in place.
    expect(PANEL_IDS).toEqual([
      'spheres', 'normal-mips', 'asphalt', 'changing-specular', 'reflect-refract', 'refraction-waves',
      'angle-ratio', 'refractive-index', 'polarization', 'exact-fresnel', 'schlick', 'r0-derivation',
      'fresnel-lighting', 'metals', 'speed-accuracy', 'stability', 'shader-lab',
    ]);
  });
  it('the README lists the same ids in the same order', () => {
    const readme = readFileSync(resolve(root, 'README.md'), 'utf8');
    const line = readme.split('\n\n').find((p) => p.includes('Panel ids are fixed'));
    expect(line, 'README: the paragraph with "Panel ids are fixed"').toBeDefined();
    expect([...line.matchAll(/`([a-z0-9-]+)`/g)].map((m) => m[1])).toEqual(PANEL_IDS);
  });
  it('the hero owns the short URL keys; other panels prefix theirs', () => {
    expect(PANELS.filter((p) => p.hero).map((p) => p.id)).toEqual(['spheres']);
    expect(lecturePrefix('spheres')).toBe('');
    expect(lecturePrefix('metals')).toBe('metals.');
  });
  it('writes each section with its id, heading, lede and citation', () => {
    const html = sectionHtml(PANELS.find((p) => p.id === 'r0-derivation'));
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
    for (const name of ['id', 'title', 'usesWebGL', 'materialParam', 'materialSelectParam']) expect(module[name]).toBeUndefined();
  });
  it('has a schema whose defaults are valid values with labels', () => {
    const keys = new Set(Object.keys(module.schema));
    for (const [key, spec] of Object.entries(module.schema)) {
      expect(spec.label, `${id}.${key} label`).toBeTruthy();
      expect(parseValue(spec, spec.default), `${id}.${key} default`).toEqual({ ok: true, value: spec.default });
      for (const alias of spec.aliases ?? []) expect(keys.has(alias), `${id}: alias ${alias} is also a key`).toBe(false);
    }
    expect(readParams(module.schema, new URLSearchParams('')).values).toEqual(defaults(module.schema));
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
      if (module.schema[key]) expect(module.schema[key].label).toMatch(key === 'nI' ? /^n_i\b/ : /^n_t\b/);
    }
    for (const spec of Object.values(module.schema)) expect(spec.label).not.toMatch(/n₁|n₂|θ₁|θ₂/);
  });
});
