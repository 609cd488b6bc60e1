#!/usr/bin/env node
// npm run panel-list: rewrites the list of the panels (scripts/panelList.js) in every Markdown file
// of the project that has its markers (docs/lecturer/panels.md), from the manifest and the English catalogue.
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { PANELS } from '../src/panels/manifest.js';
import { panelListFiles } from './panelListFiles.js';
import { panelList, withPanelList } from './panelList.js';

const root = resolve(import.meta.dirname, '..');
const words = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8')).panels;
const list = panelList(PANELS, words);
const files = panelListFiles(root);
if (!files.length) {
  console.error('No Markdown file has the panel list\'s markers (scripts/panelList.js).');
  process.exit(1);
}
for (const file of files) {
  const text = readFileSync(resolve(root, file), 'utf8');
  const written = withPanelList(text, list);
  if (written === text) console.log(`${file}: the list is up to date`);
  else {
    writeFileSync(resolve(root, file), written);
    console.log(`${file}: the list rewritten`);
  }
}
