// The docs' parameter reference (scripts/apiReference.js) is written from src/panels/manifest.js, the
// schemas and the English catalogue: every panel has its section with a row per parameter, whatever
// the panels are (tests/e2e/newPanel.spec.js runs this file in a copy with one more panel), and a
// panel left out is named. The dependency list's check (scripts/dependencyList.js) is here too.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { PANEL_IDS } from '../../src/panels/manifest.js';
import {
  apiReference, htmlHasSection, loadReferenceInputs, markdownHasSection, missingSections,
} from '../../scripts/apiReference.js';
import { unlistedDependencies } from '../../scripts/dependencyList.js';

const root = resolve(import.meta.dirname, '../..');
const inputs = await loadReferenceInputs(root);
const reference = apiReference(inputs);
const english = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8'));

/** The section of panel `id`: from its heading to the next. */
const sectionOf = (id) => {
  const start = reference.split('\n').findIndex((line) => line.startsWith('## ') && line.endsWith(`{#${id}}`));
  const rest = reference.split('\n').slice(start + 1);
  const end = rest.findIndex((line) => line.startsWith('## '));
  return rest.slice(0, end < 0 ? undefined : end).join('\n');
};
/** The cells of the row of `key` in panel `id`'s table. */
const rowOf = (id, key) => sectionOf(id).split('\n').find((line) => line.startsWith(`| \`${key}\``))?.split(' | ');

describe('the parameter reference', () => {
  it('has a section for every panel of the manifest, in its order, with a row for each parameter', () => {
    expect(missingSections(PANEL_IDS, (id) => markdownHasSection(reference, id))).toEqual([]);
    const order = [...reference.matchAll(/^## .* \{#([a-z0-9-]+)\}$/gm)].map((m) => m[1]);
    expect(order).toEqual([...PANEL_IDS]);
    for (const id of PANEL_IDS) {
      for (const key of Object.keys(inputs.schemas[id])) expect(rowOf(id, key), `${id}.${key}`).toBeDefined();
    }
  });
  it('gives each row its type, default, range and the English name of its control', () => {
    // Written out here from the schemas and the catalogue as they stand, not from the generator.
    expect(rowOf('spheres', 'nT')).toEqual(['| `nT`', 'n\\_t (sphere)', 'number', '`1.5`', '`1` to `3`, step `0.0001` |']);
    expect(rowOf('metals', 'nT')?.[0]).toBe('| `nT` (older: `n`)');
    expect(rowOf('metals', 'metal')?.[4]).toMatch(/^`gold` \(Gold\), `silver` \(Silver\)/);
    expect(rowOf('normal-mips', 'level')?.[4]).toBe('`-1` to `10`, whole numbers |');
    expect(rowOf('shader-lab', 'homework')?.slice(2, 4)).toEqual(['boolean', '`false`']);
    expect(rowOf('spheres', 'kd')?.slice(1, 4)).toEqual(['kd (diffuse)', 'color', '`#a3241c`']);
    expect(sectionOf('metals')).toContain('`metals.metal=…`');
    expect(sectionOf('spheres')).toContain('`nI=…` (the hero owns the short keys)');
  });
  it('names a control without words instead of writing a row without a name', () => {
    const controls = Object.fromEntries(Object.entries(english.controls).filter(([key]) => key !== 'schlick.theta'));
    expect(() => apiReference({ ...inputs, english: { ...english, controls } }))
      .toThrow('The panel “schlick” has no name for its control “theta” in locales/en.json (controls: “schlick.theta”).');
  });
  it('names a panel that has no section, in the Markdown or in the page as built', () => {
    const withoutMetals = reference.replace(/^## .* \{#metals\}$/m, '## Dielectrics vs metals');
    expect(missingSections(PANEL_IDS, (id) => markdownHasSection(withoutMetals, id)))
      .toEqual(['The panel “metals” has no section in the parameter reference (docs/deck/reference.md).']);
    const html = '<h2 id="spheres" tabindex="-1">Exact</h2><h3 id="metals">Metals</h3><p id="schlick"></p>';
    expect(PANEL_IDS.filter((id) => htmlHasSection(html, id))).toEqual(['spheres']);
  });
  it('keeps a name with Markdown characters as text, and the sections out of Vue\'s templates', () => {
    const panels = [{ id: 'odd', webgl: false }];
    const schemas = { odd: { k: { type: 'number', default: 0, min: 0, max: 1, step: 0.1 } } };
    const words = { panels: { 'odd.title': 'A | B' }, controls: { 'odd.k': 'x_1 * <b>y</b> | z' } };
    const markdown = apiReference({ panels, schemas, english: words });
    expect(markdown).toContain('## A \\| B {#odd}');
    expect(markdown).toContain('| x\\_1 \\* y \\| z |'); // tags dropped, as the lab's plain text drops them
    expect(markdown.startsWith('<div v-pre>')).toBe(true);
  });
});

describe('the dependency list', () => {
  const list = [
    '| package | why |', '|---|---|', '| three | peer |', '| uplot (1.6.32, pinned and patched) | plots |',
    '| @codemirror/view, state, lint | editor |', '| eslint, @eslint/js, globals | lint |',
  ].join('\n');
  it('finds each package as written, with notes in parentheses and a scope shortened after its first package', () => {
    const pkg = { dependencies: { three: '1', uplot: '1', '@codemirror/view': '1', '@codemirror/state': '1' },
      devDependencies: { '@codemirror/lint': '1', eslint: '1', '@eslint/js': '1', globals: '1' } };
    expect(unlistedDependencies(pkg, list)).toEqual([]);
  });
  it('names a package without its line', () => {
    expect(unlistedDependencies({ dependencies: { three: '1', '@codemirror/commands': '1' }, devDependencies: { why: '1' } }, list)).toEqual([
      'The package “@codemirror/commands” has no line in the dependency list (docs/developer/dependencies.md): say why it is there.',
      'The package “why” has no line in the dependency list (docs/developer/dependencies.md): say why it is there.',
    ]);
  });
  it('holds for this project', () => {
    const pkg = JSON.parse(readFileSync(resolve(root, 'package.json'), 'utf8'));
    expect(unlistedDependencies(pkg, readFileSync(resolve(root, 'docs/developer/dependencies.md'), 'utf8'))).toEqual([]);
  });
});
