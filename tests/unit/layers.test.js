// The layers of src run one way: the physics (optics) imports nothing of the page; the method
// benchmarking (methods) and the normal maps (normals) build on optics alone; the GPU glue (gl)
// on those; a model only one panel uses lives in that panel's folder. An import against the
// direction fails here, as does a module in optics that no other layer than one panel uses.
// Words and shown numbers are the exception: any layer that says something to a user takes its
// messages from src/i18n/messages.js and writes its numbers with src/ui/format.js (both pure).
// Within a panel's folder, its physics, words and runs (src/host/panelContract.js) keep the rules
// of their kind, as do the helpers of the folder they reach by their imports (a runs module that
// imports a grader that imports the catalogue writes sentences too), and what they reach by their
// imports touches no DOM and imports no CSS.
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join, normalize, relative } from 'node:path';
import { describe, expect, it } from 'vitest';

/** For each layer, the src folders its modules may import (besides itself and npm packages). */
const MAY_IMPORT = {
  optics: [],
  methods: ['optics'],
  normals: ['optics'],
  gl: ['optics', 'methods'],
};
const WORDS_AND_NUMBERS = ['src/i18n/messages.js', 'src/ui/format.js'];

function sources(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sources(path);
    return /\.(js|mjs)$/.test(entry.name) ? [relative('.', path).replaceAll('\\', '/')] : [];
  });
}

/** The repository paths a module imports relatively (static, dynamic and `new URL` workers). */
function importsOf(path) {
  const text = readFileSync(path, 'utf8');
  const specs = [...text.matchAll(/(?:from|import\s*\(|new URL\()\s*['"](\.{1,2}\/[^'"]+)['"]/g)].map((m) => m[1]);
  return specs.map((spec) => normalize(join(dirname(path), spec.split('?')[0])).replaceAll('\\', '/'));
}

/** Physics that one panel happens to use alone today, kept with the rest of the physics. */
const PHYSICS_USED_ONCE = ['src/optics/microfacet.js', 'src/optics/conductorPhase.js', 'src/optics/diffuseFresnel.js', 'src/optics/validate.js'];

const layerOf = (path) => path.split('/')[1];
const all = sources('src');

/** A module's code without its comments (a URL's // inside a string stays). */
const codeOf = (path) => readFileSync(path, 'utf8').replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|\s)\/\/.*$/gm, '$1');

/** What makes a module one of the page's: the browser's document and window, and libraries that draw. */
const DOM_GLOBALS = /\b(document|window|localStorage|sessionStorage|requestAnimationFrame|ResizeObserver|IntersectionObserver|matchMedia)\b/;
const DOM_PACKAGES = /^(lil-gui|uplot|katex|@codemirror\/)/;

/** Why a module is the page's ('' when it is not): it is CSS, imports CSS or a drawing library, or uses the DOM. */
function domUse(path) {
  if (path.endsWith('.css')) return 'is CSS';
  const text = readFileSync(path, 'utf8');
  const bare = [...text.matchAll(/(?:from|import)\s*['"]([^'"./][^'"]*)['"]/g)].map((m) => m[1]);
  const drawing = bare.find((spec) => DOM_PACKAGES.test(spec));
  if (drawing) return `imports ${drawing}`;
  const global = codeOf(path).match(DOM_GLOBALS);
  return global ? `uses ${global[1]}` : '';
}

/** The repository paths a module's code imports relatively, styles included: importsOf without the types named in comments. */
function codeImportsOf(path) {
  const specs = [...codeOf(path).matchAll(/(?:from|import\s*\(?|new URL\()\s*['"](\.{1,2}\/[^'"]+)['"]/g)].map((m) => m[1]);
  return specs.map((spec) => normalize(join(dirname(path), spec.split('?')[0])).replaceAll('\\', '/'));
}

/** Every module of src that `path` reaches by its relative imports, itself included. */
function reach(path, seen = new Set()) {
  if (seen.has(path)) return seen;
  seen.add(path);
  if (/\.(js|mjs)$/.test(path)) for (const target of codeImportsOf(path)) if (target.startsWith('src/')) reach(target, seen);
  return seen;
}

/** "module (via a → b): why" for each module `roots` reach that is the page's. */
function domReached(roots) {
  return roots.flatMap((root) => [...reach(root)].map((path) => [path, domUse(path)]).filter(([, why]) => why)
    .map(([path, why]) => `${root} reaches ${path}: it ${why}`));
}

/**
 * The modules of its own folder that a kind's module reaches by its imports, itself included: its
 * helpers (gradingCases.js, sceneSettings.js …) keep the kind's rules, as docs/panels.md says.
 */
function folderReach(path) {
  const folder = `${dirname(path)}/`;
  const seen = new Set();
  const visit = (p) => {
    if (seen.has(p) || !p.startsWith(folder) || !/\.(js|mjs)$/.test(p)) return;
    seen.add(p);
    codeImportsOf(p).forEach(visit);
  };
  visit(path);
  return [...seen];
}

/** "module" or "module (via helper)" for each of a kind's modules, with every helper of its folder it reaches. */
const withHelpers = (kindPaths) => kindPaths.flatMap((root) => folderReach(root).map((p) => ({ root, path: p })));
const named = ({ root, path }) => (path === root ? root : `${root} (via ${path})`);

const PANEL_KINDS = ['physics', 'words', 'runs'];
const panelFolders = readdirSync('src/panels', { withFileTypes: true }).filter((e) => e.isDirectory()).map((e) => `src/panels/${e.name}`);
const kindModules = (kind) => all.filter((p) => p.startsWith('src/panels/') && p.split('/').length === 4 && p.endsWith(`/${kind}.js`));
const WORDS = /virtual:messages\//;

describe('layers', () => {
  for (const [layer, allowed] of Object.entries(MAY_IMPORT)) {
    it(`src/${layer} imports only ${allowed.length ? allowed.join(', ') : 'itself'}`, () => {
      const files = all.filter((p) => layerOf(p) === layer);
      expect(files.length).toBeGreaterThan(2);
      const wrong = files.flatMap((p) =>
        importsOf(p)
          .filter((target) => target.startsWith('src/') && ![layer, ...allowed].includes(layerOf(target)))
          .filter((target) => !WORDS_AND_NUMBERS.includes(target))
          .map((target) => `${p} → ${target}`));
      expect(wrong).toEqual([]);
    });
  }

  it('keeps in src/optics the physics and what more than one panel, or another layer, uses', () => {
    const users = new Map();
    for (const p of all) {
      for (const target of importsOf(p)) {
        if (!target.startsWith('src/optics/') || layerOf(p) === 'optics') continue;
        const user = p.startsWith('src/panels/') ? p.split('/').slice(0, 3).join('/') : layerOf(p);
        if (!users.has(target)) users.set(target, new Set());
        users.get(target).add(user);
      }
    }
    const onePanelOnly = [...users].filter(([target, who]) =>
      who.size === 1 && [...who][0].startsWith('src/panels/') && !PHYSICS_USED_ONCE.includes(target));
    expect(onePanelOnly.map(([target, who]) => `${target} (only ${[...who][0]})`)).toEqual([]);
  });
});

describe('the kinds of a panel\'s modules', () => {
  it('names every panel module by its kind: no folder keeps a model.js', () => {
    expect(panelFolders.filter((dir) => all.includes(`${dir}/model.js`))).toEqual([]);
    for (const kind of PANEL_KINDS) expect(kindModules(kind).length, kind).toBeGreaterThan(1);
  });

  it('physics.js, and what it reaches in its folder, imports only src/optics, src/methods, src/normals and its folder\'s physics', () => {
    const wrong = withHelpers(kindModules('physics')).flatMap((reached) => {
      const { path } = reached;
      const bare = [...readFileSync(path, 'utf8').matchAll(/(?:from|import)\s*['"]([^'"./][^'"]*)['"]/g)].map((m) => m[1]);
      return [
        ...importsOf(path).filter((target) => !['optics', 'methods', 'normals'].includes(layerOf(target)) && target !== reached.root),
        ...bare,
      ].map((target) => `${named(reached)} → ${target}`);
    });
    expect(wrong).toEqual([]);
  });

  it('physics.js and runs.js, and the helpers they reach in their folder, write no sentence: no words from the catalogue', () => {
    const wrong = withHelpers([...kindModules('physics'), ...kindModules('runs')]).filter(({ path }) => {
      const text = readFileSync(path, 'utf8');
      return WORDS.test(text) || importsOf(path).some((target) => ['src/i18n/messages.js', 'src/panels/panelText.js'].includes(target));
    }).map(named);
    expect(wrong).toEqual([]);
  });

  it('runs.js exports its create<Name>Runs', () => {
    const missing = kindModules('runs').filter((p) => !/export function create[A-Z]\w*Runs\(/.test(readFileSync(p, 'utf8')));
    expect(missing).toEqual([]);
  });

  it('nothing a physics, words or runs module reaches by its imports touches the DOM or imports CSS', () => {
    expect(domReached(PANEL_KINDS.flatMap(kindModules))).toEqual([]);
  });
});

describe('the pages\' layers', () => {
  const under = (...dirs) => all.filter((p) => dirs.some((dir) => p.startsWith(`${dir}/`)));

  it('src/homework/class is pure: nothing it reaches touches the DOM or imports CSS', () => {
    expect(under('src/homework/class').length).toBeGreaterThan(2);
    expect(domReached(under('src/homework/class'))).toEqual([]);
  });

  it('src/lecture and src/compose use no part of the homework page: shared parts are src/ui\'s', () => {
    const wrong = under('src/lecture', 'src/compose').flatMap((p) => codeImportsOf(p)
      .filter((target) => target.startsWith('src/homework/page/')).map((target) => `${p} → ${target}`));
    expect(wrong).toEqual([]);
  });

  it('src/lecture and src/compose write no class of the homework page (hw-…) of their own', () => {
    const wrong = under('src/lecture', 'src/compose').filter((p) => /['"` ]hw-[a-z]/.test(codeOf(p)));
    expect(wrong).toEqual([]);
  });

  it('src/ui, the pages\' kit, imports no page and no panel', () => {
    const wrong = under('src/ui').flatMap((p) => codeImportsOf(p)
      .filter((target) => ['homework', 'compose', 'lecture', 'panels'].includes(layerOf(target))).map((target) => `${p} → ${target}`));
    expect(wrong).toEqual([]);
  });
});
