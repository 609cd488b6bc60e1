// The metals of the materials table, read in Node for browser tests.
import { readFileSync } from 'node:fs';

export const metals = JSON.parse(readFileSync('src/optics/materials.json', 'utf8')).metals;
