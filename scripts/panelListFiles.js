// The Markdown files that hold the panel list (scripts/panelList.js): README.md or any page under
// docs/ with its start marker, as paths from the repository's root.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { LIST_START } from './panelList.js';

function markdownUnder(root, dir) {
  if (!existsSync(join(root, dir))) return [];
  return readdirSync(join(root, dir), { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return entry.name === 'node_modules' || entry.name.startsWith('.') ? [] : markdownUnder(root, path);
    return entry.name.endsWith('.md') ? [path.replaceAll('\\', '/')] : [];
  });
}

/** @param {string} root the repository's root */
export function panelListFiles(root) {
  return ['README.md', ...markdownUnder(root, 'docs')]
    .filter((file) => existsSync(join(root, file)) && readFileSync(join(root, file), 'utf8').includes(LIST_START));
}
