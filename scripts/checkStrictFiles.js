// The strict type check (jsconfig.strict.json) must cover every reader of outside data, and read
// every file it lists. Two rules, run by `npm run typecheck` (exit 1 when one is broken):
// - A module of src that reads outside data (outsideDataReaders.js: storage, the link, messages,
//   files, fetched bodies, decoders) is in the config's `include`, by its folder or by its name, so a
//   new reader cannot be left out of the check.
// - Each JavaScript file of the `include` starts with `// @ts-check`: the config leaves checkJs off so
//   that the modules its files import from other folders are not held to strict too, and a file
//   without the line would pass unread.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative, resolve } from 'node:path';
import ts from 'typescript';
import { waysIn } from './outsideDataReaders.js';

const CONFIG = 'jsconfig.strict.json';

const parsed = ts.getParsedCommandLineOfConfigFile(CONFIG, {}, {
  ...ts.sys,
  onUnRecoverableConfigFileDiagnostic: (diagnostic) => {
    throw new Error(ts.flattenDiagnosticMessageText(diagnostic.messageText, '\n'));
  },
});
const files = parsed.fileNames.filter((path) => path.endsWith('.js'));
const strict = new Set(files.map((path) => resolve(path)));

/** @param {string} dir @returns {string[]} every .js module under dir */
const modules = (dir) => readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
  const path = join(dir, entry.name);
  if (entry.isDirectory()) return modules(path);
  return entry.name.endsWith('.js') ? [path] : [];
});

const outside = modules('src').map((path) => [path, waysIn(readFileSync(path, 'utf8'))])
  .filter(([path, ways]) => ways.length && !strict.has(resolve(path)));
for (const [path, ways] of outside) {
  console.error(`${relative('.', path)}: reads outside data (${ways.join('; ')}) but ${CONFIG} does not include it:`
    + ' add it to "include" and start it with // @ts-check');
}
const unchecked = files.filter((path) => !/^\s*\/\/ @ts-check\b/.test(readFileSync(path, 'utf8')));
for (const path of unchecked) console.error(`${relative('.', path)}: no // @ts-check on its first line, so ${CONFIG} does not check it`);
if (!files.length) console.error(`${CONFIG} includes no JavaScript file`);
process.exit(outside.length || unchecked.length || !files.length ? 1 : 0);
