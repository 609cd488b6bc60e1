import { defineConfig } from 'vite';
import { readdirSync, existsSync, readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { createRequire } from 'node:module';
import { viteSingleFile } from 'vite-plugin-singlefile';
import { PANELS, PLACES_MARKER, SECTIONS_MARKER, manifestProblems, panelTextFrom, placesCss, sectionHtml } from './src/panels/manifest.js';
import { contentSecurityPolicy, inlineTexts, withPolicyMeta } from './scripts/contentSecurityPolicy.js';
import { messagesPlugin } from './scripts/messagesPlugin.js';

const root = import.meta.dirname;

/** The panels' own files, as `<folder>/index.js` and `<folder>/schema.js` under src/panels. */
function panelFiles() {
  const dir = resolve(root, 'src/panels');
  return readdirSync(dir, { withFileTypes: true }).filter((d) => d.isDirectory())
    .flatMap((d) => ['index.js', 'schema.js'].filter((file) => existsSync(resolve(dir, d.name, file))).map((file) => `${d.name}/${file}`));
}

/**
 * The lecture page's sections and the places they keep come from the panel manifest: written
 * into index.html and src/panelPlaces.css at build (and dev) time, so the page is readable and
 * laid out before any script runs. The build fails when the manifest, the panel folders and the
 * page disagree.
 */
function panelManifest() {
  const placesFile = resolve(root, 'src/panelPlaces.css');
  // The panels' words: the English catalogue's "panels" namespace (read afresh, so an edit shows).
  const panelWords = () => JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8')).panels ?? {};
  const check = () => {
    const problems = manifestProblems(panelFiles(), panelWords(), readFileSync(resolve(root, 'index.html'), 'utf8'));
    if (problems.length) throw new Error(`Panel manifest (src/panels/manifest.js):\n  ${problems.join('\n  ')}`);
  };
  return {
    name: 'fresnel-lab-panel-manifest',
    buildStart: check,
    transform: {
      order: 'pre', // before vite's CSS plugin reads it
      handler(code, id) {
        if (id.split('?')[0] !== placesFile) return null;
        if (!code.includes(PLACES_MARKER)) throw new Error(`src/panelPlaces.css has no place for the panels' places (${PLACES_MARKER}).`);
        return code.replace(PLACES_MARKER, placesCss());
      },
    },
    transformIndexHtml: {
      order: 'pre',
      handler(html, { filename }) {
        if (!filename.endsWith('index.html') || filename.endsWith('embed.html')) return html;
        check();
        const words = panelWords();
        return html.replace(SECTIONS_MARKER, PANELS.map((entry) => sectionHtml(entry, panelTextFrom(words, entry.id))).join('\n\n    '));
      },
    },
  };
}

/**
 * For the single-file pages: every `?worker` import becomes `?worker&inline` (the worker's code
 * travels in the page and starts from a blob: URL, since a page opened from disk may not load a
 * worker file), and KaTeX's fonts keep only their WOFF2 files (which every browser that runs
 * WebGL2 reads), so the page carries each font once.
 */
function offlineAssets() {
  return {
    name: 'fresnel-lab-offline-assets',
    enforce: 'pre',
    async resolveId(source, importer, options) {
      if (!source.endsWith('?worker')) return null;
      const resolved = await this.resolve(source.slice(0, -'?worker'.length), importer, { ...options, skipSelf: true });
      return resolved && `${resolved.id}?worker&inline`;
    },
    transform(code, id) {
      if (!/katex(\.min)?\.css$/.test(id)) return null;
      return code.replace(/,\s*url\([^)]*\.woff\)\s*format\("woff"\)/g, '').replace(/,\s*url\([^)]*\.ttf\)\s*format\("truetype"\)/g, '');
    },
  };
}

/**
 * Every built page carries its Content-Security-Policy as a meta (scripts/contentSecurityPolicy.js).
 * Build only: the dev server's own inline scripts (HMR) would be refused. Runs after the single-file
 * plugin has inlined a page's script and style, so their hashes are of what the page holds.
 */
function policyMeta() {
  return {
    name: 'fresnel-lab-csp-meta',
    apply: 'build',
    enforce: 'post',
    generateBundle: {
      order: 'post',
      handler(_options, bundle) {
        for (const file of Object.values(bundle)) {
          if (file.type !== 'asset' || !file.fileName.endsWith('.html')) continue;
          const html = String(file.source);
          const policy = contentSecurityPolicy({ singleFile: Boolean(singleFile), ...inlineTexts(html) });
          file.source = withPolicyMeta(html, policy);
        }
      },
    },
  };
}

// FRESNEL_LAB_SINGLE_FILE=index|embed builds that page alone into dist/offline as one HTML file
// (scripts, styles, fonts and workers inlined by vite-plugin-singlefile), which works opened from
// disk and in a sandboxed iframe; scripts/buildOffline.js runs both after the ordinary build.
const singleFile = process.env.FRESNEL_LAB_SINGLE_FILE;

/**
 * The chunks of the lab's shared layers by the pages that import them statically, known once the
 * module graph is complete. Of the layers (`shared`, and all that they import), a module goes in the
 * first chunk of `chunks` whose rule takes it: rule(imports, id), where imports(page) tells whether
 * that page of `pages` imports the module statically (through any chain of imports).
 */
function layerChunks(shared, pages, chunks) {
  /** @type {Map<string, string>} module id → its chunk's name */
  const chunkOf = new Map();
  /** Every module the modules `from` import statically, themselves included. */
  const closure = (context, from) => {
    const reached = new Set();
    const stack = [...from];
    while (stack.length) {
      const id = stack.pop();
      if (reached.has(id)) continue;
      reached.add(id);
      stack.push(...(context.getModuleInfo(id)?.importedIds ?? []));
    }
    return reached;
  };
  return {
    test: (name) => (id) => chunkOf.get(id) === name,
    plugin: {
      name: 'fresnel-lab-layer-chunks',
      apply: 'build',
      buildEnd() {
        const layers = closure(this, [...this.getModuleIds()].filter((id) => shared.some((test) => test.test(id))));
        const reached = Object.fromEntries(Object.entries(pages).map(([page, entry]) => [page, closure(this, [entry])]));
        chunkOf.clear();
        for (const id of layers) {
          const name = Object.keys(chunks).find((chunk) => chunks[chunk]((page) => reached[page].has(id), id));
          if (name) chunkOf.set(id, name);
        }
      },
    },
  };
}

// The lab's shared layers: the host and the page's parts, the language, the panels' schemas and titles.
const SHARED_LAYERS = /src[\\/](host|ui|i18n)[\\/]|src[\\/]panels[\\/]([\w-]+[\\/]schema|shared[\\/]indexPair|manifest|panelText|controlText|panelSchema|loadPanel)\.js|virtual:messages[\\/]en[\\/](panels:title\+titleHtml|controls|page|host|ui)$|node_modules[\\/]lil-gui[\\/]/;
// The shared parts the hero and most panels use, with their words (panelsShared, the materials' names).
const PANEL_SHARED = /src[\\/]panels[\\/]shared[\\/](indexPresets|startWebGL|dielectricTrace|materialName|indexText)\.js|virtual:messages[\\/]en[\\/](panelsShared|materials)$/;

const pages = {
  index: resolve(root, 'index.html'),
  embed: resolve(root, 'embed.html'),
  homework: resolve(root, 'homework.html'),
  // The lecture composer (src/compose/): a lecture of one's own from the panels, as a link.
  compose: resolve(root, 'compose.html'),
  // An example reveal.js deck with embedded panels (examples/deck.html), shipped with the site.
  deck: resolve(root, 'examples/deck.html'),
  // npm run bench also builds the three.js peer the hero is measured against, and the real-GPU
  // check's page (bench/gpu/); neither is shipped.
  ...(process.env.FRESNEL_LAB_BENCH_PEER === '1'
    ? { peer: resolve(root, 'bench/peer.html'), gpu: resolve(root, 'bench/gpu/gpu.html') } : {}),
};
// 'base': what the homework page or the composer imports (every page loads it); 'core': what both the
// lecture page and an embed add (the panel host, lil-gui, the controls' names, the audio trace). What
// only one of those two imports stays in that page's own chunk (the lecture mode; the message API),
// but for the typesetting helper, which the lecture page imports and an embed's formula panels do:
// a chunk of its own would cost those embeds more than its place in 'core' costs the others.
const layers = layerChunks([SHARED_LAYERS, PANEL_SHARED], {
  ...pages,
  // What those two pages fetch at once for their first picture: a student's sheet or the lecturer's
  // page, and an item's editor (but a panel item's start, which takes the controls' names from 'core').
  sheet: resolve(root, 'src/homework/page/showSheet.js'),
  lecturer: resolve(root, 'src/homework/page/lecturerPage.js'),
  itemEditor: resolve(root, 'src/compose/buildItemEditor.js'),
}, {
  base: (imports) => ['homework', 'compose', 'sheet', 'lecturer', 'itemEditor'].some(imports),
  core: (imports, id) => imports('index') && (imports('embed') || /src[\\/]ui[\\/]tex\.js$/.test(id)),
});

// Relative base: the built site works from any sub-path (a course page, a USB stick).
export default defineConfig({
  base: './',
  // The message catalogues (locales/*.json) first: the pages' own words are written from them, and
  // the manifest's sections after them.
  plugins: singleFile
    ? [messagesPlugin({ dir: resolve(root, 'locales'), pseudo: false }), panelManifest(), offlineAssets(), viteSingleFile(), policyMeta()]
    : [messagesPlugin({ dir: resolve(root, 'locales') }), panelManifest(), policyMeta(), layers.plugin],
  // Workers are bundled apart, with these plugins only: the modules they share with the page (the
  // methods and their scenes, the class view's grading) import their words from the catalogue too.
  worker: { plugins: () => [messagesPlugin({ dir: resolve(root, 'locales'), pseudo: !singleFile })] },
  build: {
    ...(singleFile ? { outDir: 'dist/offline', emptyOutDir: false } : {}),
    target: 'es2022',
    // Fonts stay files (font-src 'self' in the pages' CSP); the single-file plugin inlines everything.
    ...(singleFile ? {} : { assetsInlineLimit: (file) => (/\.(woff2?|ttf)$/.test(file) ? false : undefined) }),
    // The largest chunk is the benchmark's three.js peer (about 540 KB), fetched only when a benchmark
    // run reaches it; the next is the shader lab's editor (about 380 KB), loaded with that panel alone.
    chunkSizeWarningLimit: 700,
    // dist/.vite/manifest.json: which chunks each page and panel imports, for the first-load budget's test.
    ...(singleFile ? {} : { manifest: true }),
    rollupOptions: {
      input: singleFile ? pages[singleFile] : pages,
      // The code the pages load at once in two chunks (layerChunks above) rather than in one per
      // combination of pages that share it: dozens of small files cost the first load more than
      // their contents (each is compressed alone); one chunk for all would give the homework page
      // and the composer the panel host they never use. Only what an entry imports statically ($initial).
      output: singleFile ? {} : {
        codeSplitting: {
          groups: [{
            name: 'base',
            tags: ['$initial'],
            test: layers.test('base'),
          }, {
            name: 'core',
            tags: ['$initial'],
            test: layers.test('core'),
          }, {
            // The shared parts the hero and most panels use, with their words (panelsShared, the
            // materials' names): one chunk, not five small ones each compressed alone.
            name: 'panelShared',
            test: PANEL_SHARED,
          }],
        },
      },
    },
  },
  resolve: {
    // lil-gui's stylesheet, which its package does not export: imported by styles.css as a file,
    // since the pages' CSP refuses the <style> lil-gui would inject.
    alias: { 'lil-gui/dist/lil-gui.css': resolve(dirname(createRequire(import.meta.url).resolve('lil-gui')), 'lil-gui.css') },
  },
  server: { host: '127.0.0.1' },
  preview: { host: '127.0.0.1' },
  test: {
    include: ['tests/unit/**/*.test.js'],
    environment: 'node',
    // Pure modules with no shared state: one import per worker instead of one per file halves the run.
    pool: 'threads',
    isolate: false,
    // CSS is left out of unit tests, but for KaTeX's, which the deck export carries as text (katexDeckCss.js).
    css: { include: [/katex\.min\.css/] },
    // A few tests sweep fine grids (about a second alone); on a busy two-core machine they take
    // several times that. A test that hangs still fails, after 30 s.
    testTimeout: 30_000,
  },
});
