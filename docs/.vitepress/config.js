// The documentation site (VitePress): `npm run docs:dev`, `npm run docs:build` (into
// docs/.vitepress/dist, apart from the lab's dist/). The build fails on a link to a page that does
// not exist (VitePress's own check, left strict), on a panel without its section in the parameter
// reference, which is written here from the panels' schemas, and on a package without its line in the
// dependency list.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitepress';
import { PANEL_IDS } from '../../src/panels/manifest.js';
import {
  REFERENCE_MARKER, apiReference, htmlHasSection, loadReferenceInputs, markdownHasSection, missingSections,
} from '../../scripts/apiReference.js';
import { unlistedDependencies } from '../../scripts/dependencyList.js';

const root = fileURLToPath(new URL('../..', import.meta.url));
const at = (path) => fileURLToPath(new URL(path, new URL('../..', import.meta.url)));

/** Stops the build with every problem named. */
function fail(what, problems) {
  if (problems.length) throw new Error(`${what}:\n  ${problems.join('\n  ')}`);
}

const reference = apiReference(await loadReferenceInputs(root));
fail('Parameter reference', missingSections(PANEL_IDS, (id) => markdownHasSection(reference, id)));
fail('Dependency list', unlistedDependencies(JSON.parse(readFileSync(at('package.json'), 'utf8')),
  readFileSync(at('docs/developer/dependencies.md'), 'utf8')));

/** The reference's sections go where docs/deck/reference.md has the marker, before Markdown is read. */
function referencePlugin(md) {
  md.core.ruler.before('normalize', 'fresnel-lab-reference', (state) => {
    if (state.src.includes(REFERENCE_MARKER)) state.src = state.src.replace(REFERENCE_MARKER, () => reference);
  });
}

/** Inline code is text to Vue too: the message catalogue's `{{n} students}` is no template. */
function inlineCodeAsText(md) {
  const render = md.renderer.rules.code_inline;
  md.renderer.rules.code_inline = (...args) => render(...args).replace(/^<code/, '<code v-pre');
}

const lecturer = [
  { text: 'Present the lab', link: '/lecturer/present' },
  { text: 'The panels', link: '/lecturer/panels' },
  { text: 'Host it, or carry it offline', link: '/lecturer/offline' },
  { text: 'Compose a lecture', link: '/lecturer/compose' },
  { text: 'Set homework', link: '/lecturer/homework' },
  { text: 'Grade a class', link: '/lecturer/grade' },
  { text: 'SCORM and your LMS', link: '/lecturer/lms' },
];
const student = [
  { text: 'Explore the lab', link: '/student/explore' },
  { text: 'Do the homework', link: '/student/homework' },
  { text: 'Your language', link: '/student/language' },
];
const deck = [
  { text: 'Embed a panel', link: '/deck/embed' },
  { text: 'The message API', link: '/deck/messages' },
  { text: 'In a reveal.js deck', link: '/deck/reveal' },
  { text: 'Panel parameters', link: '/deck/reference' },
];
const developer = [
  { text: 'Architecture', link: '/developer/architecture' },
  { text: 'Writing a panel', link: '/panels' },
  { text: 'Words in every language', link: '/i18n' },
  { text: 'Testing', link: '/developer/testing' },
  { text: 'Performance', link: '/developer/performance' },
  { text: 'Benchmark results', link: '/developer/benchmarks' },
  { text: 'Dependencies', link: '/developer/dependencies' },
];

export default defineConfig({
  title: 'Fresnel Lab',
  description: 'An interactive WebGL2 lab for one graphics lecture: mipmapping normal maps and Fresnel reflection.',
  lang: 'en',
  // Left strict on purpose: a link to a page that does not exist fails the build.
  ignoreDeadLinks: false,
  markdown: { config: (md) => { referencePlugin(md); inlineCodeAsText(md); } },
  themeConfig: {
    nav: [
      { text: 'Lecturer', link: lecturer[0].link },
      { text: 'Student', link: student[0].link },
      { text: 'Deck author', link: deck[0].link },
      { text: 'Developer', link: developer[0].link },
    ],
    sidebar: [
      { text: 'Lecturer', items: lecturer },
      { text: 'Student', items: student },
      { text: 'Deck author', items: deck },
      { text: 'Developer', items: developer },
    ],
    outline: [2, 3],
    search: { provider: 'local' },
  },
  /** The pages as built: the reference has every panel's section, the benchmark page its results. */
  buildEnd({ outDir }) {
    const html = readFileSync(`${outDir}/deck/reference.html`, 'utf8');
    fail('Parameter reference as built', missingSections(PANEL_IDS, (id) => htmlHasSection(html, id)));
    const bench = readFileSync(`${outDir}/developer/benchmarks.html`, 'utf8');
    fail('Benchmark results as built', bench.includes('id="benchmark-speed-against-accuracy"') ? []
      : ['docs/developer/benchmarks.md shows no bench/RESULTS.md (its include found nothing).']);
  },
});
