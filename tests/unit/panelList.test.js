// The list of the panels in the docs (docs/lecturer/panels.md) is the one scripts/panelList.js writes from
// the manifest and the catalogue: a panel added, moved or renamed fails here until
// `npm run panel-list` has rewritten it.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { PANELS } from '../../src/panels/manifest.js';
import { LIST_END, LIST_START, markdownText, panelList, withPanelList } from '../../scripts/panelList.js';
import { panelListFiles } from '../../scripts/panelListFiles.js';

const root = resolve(import.meta.dirname, '../..');
const words = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8')).panels;
const listIn = (text) => text.slice(text.indexOf(LIST_START), text.indexOf(LIST_END) + LIST_END.length);

describe('the list of the panels', () => {
  const files = panelListFiles(root);
  it('is in the project\'s Markdown', () => {
    expect(files.length).toBeGreaterThan(0);
  });
  it.each(files)('%s: is what the manifest and the catalogue give (else: npm run panel-list)', (file) => {
    expect(listIn(readFileSync(resolve(root, file), 'utf8'))).toBe(panelList(PANELS, words));
  });
  it('has each panel once, in the manifest\'s order, by its id and its English title', () => {
    const rows = panelList(PANELS, words).split('\n').filter((line) => /^\| \d/.test(line));
    expect(rows.map((row) => row.split(' | ')[2])).toEqual(PANELS.map((p) => `\`${p.id}\``));
    expect(rows[0]).toBe('| 1 | Exact Fresnel vs Schlick\'s approximation | `spheres` | WebGL | '
      + 'Lecture: “Reflection Math”, “Fresnel Reflection in Lighting”. |');
    expect(rows.find((row) => row.includes('`speed-accuracy`'))).toContain('| WebGL while it measures |');
    expect(rows.find((row) => row.includes('`schlick`'))).toContain('| no WebGL |');
  });
  it('is stale once a panel is added, and rewriting puts it in', () => {
    const readme = `# Lab\n\n${panelList(PANELS.slice(0, 2), words)}\n\nMore.\n`;
    const rewritten = withPanelList(readme, panelList(PANELS, words));
    expect(listIn(readme)).not.toBe(panelList(PANELS, words));
    expect(listIn(rewritten)).toBe(panelList(PANELS, words));
    expect(rewritten.startsWith('# Lab\n\n') && rewritten.endsWith('\n\nMore.\n')).toBe(true);
    expect(withPanelList('# Lab, no list\n', panelList(PANELS, words))).toBeNull();
  });
});

describe('a catalogue message in a Markdown table cell', () => {
  it('keeps the lab\'s notation, its emphasis and its entities, and cannot break the table', () => {
    expect(markdownText('n<sub>t</sub>/n<sub>i</sub> and (1 − cos θ)<sup>5</sup>')).toBe('n_t/n_i and (1 − cos θ)^5');
    expect(markdownText('Hecht, <i>Optics</i>, §4.6; Olano &amp; Baker')).toBe('Hecht, *Optics*, §4.6; Olano & Baker');
    expect(markdownText('a | b, [0, 1], 2 * 3, &lt;b&gt;, `x`\n  wrapped')).toBe('a \\| b, \\[0, 1\\], 2 \\* 3, &lt;b>, \\`x\\` wrapped');
    expect(markdownText('<a href="https://x.example">a link</a>')).toBe('a link');
  });
});
