// The strict type check (jsconfig.strict.json) reads a JavaScript file only if the file starts with
// `// @ts-check`: the config leaves checkJs off so that the modules its files import from other
// folders are not held to strict too. A file of its `include` without the line would pass unread,
// so this names each one. Run by `npm run typecheck`; exits 1 when there is one.
import { readFileSync } from 'node:fs';
import { relative } from 'node:path';
import ts from 'typescript';

const CONFIG = 'jsconfig.strict.json';

const parsed = ts.getParsedCommandLineOfConfigFile(CONFIG, {}, {
  ...ts.sys,
  onUnRecoverableConfigFileDiagnostic: (diagnostic) => {
    throw new Error(ts.flattenDiagnosticMessageText(diagnostic.messageText, '\n'));
  },
});
const files = parsed.fileNames.filter((path) => path.endsWith('.js'));
const unchecked = files.filter((path) => !/^\s*\/\/ @ts-check\b/.test(readFileSync(path, 'utf8')));
for (const path of unchecked) console.error(`${relative('.', path)}: no // @ts-check on its first line, so ${CONFIG} does not check it`);
if (!files.length) console.error(`${CONFIG} includes no JavaScript file`);
process.exit(unchecked.length || !files.length ? 1 : 0);
