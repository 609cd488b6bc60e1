// A copy of the project with one panel added as docs/panels.md says: its folder and its manifest
// entry, nothing else. The copy links to the project's node_modules; what it builds stays in it.
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { execFile } from 'node:child_process';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';

const root = resolve(import.meta.dirname, '../..');
/** What `npm run build` and the unit tests read (the benchmark's peer page is built only for it). */
const PROJECT = ['index.html', 'embed.html', 'homework.html', 'compose.html', 'vite.config.js', 'package.json', 'jsconfig.json',
  'README.md', 'docs', 'locales', 'src', 'shaders', 'public', 'examples', 'scripts', 'tests/unit'];

/**
 * The smallest panel of docs/panels.md, as written there: its files by path (the blocks whose
 * first lines name src/panels/<id>/schema.js or index.js), its manifest entry and its words (the
 * JSON block for locales/en.json).
 */
export function docsPanel() {
  const blocks = [...readFileSync(join(root, 'docs/panels.md'), 'utf8').matchAll(/```js\n([\s\S]*?)```/g)].map((m) => m[1]);
  const files = {};
  for (const block of blocks) {
    const path = block.split('\n', 2).join('\n').match(/^\/\/ (src\/panels\/[a-z0-9-]+\/(?:schema|index)\.js)$/m)?.[1];
    if (path) files[path] = block;
  }
  const entry = blocks.find((block) => block.startsWith('// src/panels/manifest.js'));
  const json = [...readFileSync(join(root, 'docs/panels.md'), 'utf8').matchAll(/```json\n\/\/ locales\/en\.json[^\n]*\n([\s\S]*?)```/g)][0]?.[1];
  return { id: entry?.match(/\bid: '([a-z0-9-]+)'/)?.[1], files, entry, words: json ? JSON.parse(json) : null };
}

/** A copy of the project with `panel` added: its files, and its entry last in the manifest. */
export function scaffold(panel) {
  const dir = mkdtempSync(join(tmpdir(), 'fresnel-lab-new-panel-'));
  // Not the docs site's build output or cache (docs/.vitepress/dist, cache), which only slow the copy.
  const notBuilt = (source) => !/[\\/]docs[\\/]\.vitepress[\\/](dist|cache)$/.test(source);
  for (const path of PROJECT) cpSync(join(root, path), join(dir, path), { recursive: true, filter: notBuilt });
  symlinkSync(join(root, 'node_modules'), join(dir, 'node_modules'), 'dir');
  for (const [path, text] of Object.entries(panel.files)) {
    mkdirSync(dirname(join(dir, path)), { recursive: true });
    writeFileSync(join(dir, path), text);
  }
  editFile(dir, 'locales/en.json', (text) => {
    const catalogue = JSON.parse(text);
    for (const [namespace, words] of Object.entries(panel.words ?? {})) catalogue[namespace] = { ...catalogue[namespace], ...words };
    return `${JSON.stringify(catalogue, null, 2)}\n`;
  });
  editFile(dir, 'src/panels/manifest.js', (text) => {
    const end = text.indexOf('\n]);', text.indexOf('export const PANELS'));
    return `${text.slice(0, end)}\n${panel.entry.trimEnd()}${text.slice(end)}`;
  });
  return dir;
}

/** Rewrites a file of the copy. */
export function editFile(dir, path, edit) {
  writeFileSync(join(dir, path), edit(readFileSync(join(dir, path), 'utf8')));
}

export const removeCopy = (dir) => rmSync(dir, { recursive: true, force: true });

/**
 * Runs a command in the copy: { code, output } (stdout and stderr), never a throw. The page
 * variables of the tests' own build are left out: the copy builds as `npm run build` does.
 */
export function runIn(dir, command, args) {
  const env = { ...process.env };
  for (const name of ['FRESNEL_LAB_SINGLE_FILE', 'FRESNEL_LAB_BENCH_PEER']) delete env[name];
  return new Promise((done) => {
    execFile(command, args, { cwd: dir, env, maxBuffer: 32 << 20 }, (error, stdout, stderr) => {
      done({ code: error ? (error.code ?? 1) : 0, output: `${stdout}${stderr}` });
    });
  });
}
