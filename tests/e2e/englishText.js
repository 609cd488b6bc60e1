// The English catalogue (locales/en.json) as the browser tests read it: what a page in English must show.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

export const english = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../locales/en.json'), 'utf8'));

/** A panel's title as plain text. */
export const englishPanelTitle = (id) => english.panels[`${id}.title`];
