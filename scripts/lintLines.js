// The lint rules for the files ESLint does not read (CSS, GLSL, HTML), run by `npm run lint`:
// - no line of src or shaders is longer than 140 characters, as max-len holds for the JavaScript
//   (a page that reads on a laptop beside the running lab, a review diff with no sideways scrolling);
// - every style sheet lays out by reading direction (scripts/physicalCss.js): no physical left or
//   right unless a comment says it is geometry, no words in CSS, no change of direction without its
//   reason, so that a right-to-left language is a catalogue and a line in languages.js, no CSS.
// Prints each problem and exits 1 when there is one.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { directionProblems } from './physicalCss.js';

export const LIMIT = 140;

function sources(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sources(path);
    return /\.(css|glsl|html)$/.test(entry.name) ? [relative('.', path).replaceAll('\\', '/')] : [];
  });
}

const files = ['src', 'shaders'].flatMap(sources);
const long = files.flatMap((path) => readFileSync(path, 'utf8').split('\n')
  .flatMap((line, i) => ([...line].length > LIMIT ? [`${path}:${i + 1}: ${[...line].length} characters (at most ${LIMIT})`] : [])));
const physical = files.filter((path) => path.endsWith('.css'))
  .flatMap((path) => directionProblems(readFileSync(path, 'utf8')).map((problem) => `${path} ${problem}`));
const problems = [...long, ...physical];
for (const line of problems) console.error(line);
process.exit(problems.length ? 1 : 0);
