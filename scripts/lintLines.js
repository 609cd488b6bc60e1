// The line-length rule for the files ESLint does not read (CSS, GLSL, HTML): no line of src or
// shaders is longer than 140 characters, as max-len holds for the JavaScript (a page
// that reads on a laptop beside the running lab, a review diff with no sideways scrolling).
// Run by `npm run lint`; prints each long line and exits 1 when there is one.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';

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
for (const line of long) console.error(line);
process.exit(long.length ? 1 : 0);
