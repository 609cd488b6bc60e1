// The layers of src run one way: the physics (optics) imports nothing of the page; the method
// benchmarking (methods) and the normal maps (normals) build on optics alone; the GPU glue (gl)
// on those; a model only one panel uses lives in that panel's folder. An import against the
// direction fails here, as does a module in optics that no other layer than one panel uses.
// Words and shown numbers are the exception: any layer that says something to a user takes its
// messages from src/i18n/messages.js and writes its numbers with src/ui/format.js (both pure).
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
