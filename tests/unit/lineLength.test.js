// No line of the sources is longer than 140 characters: a page that reads on a laptop beside the
// running lab, and a review diff that needs no sideways scrolling.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { expect, it } from 'vitest';

const LIMIT = 140;

function sources(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sources(path);
    return /\.(js|mjs|css|glsl|html)$/.test(entry.name) ? [relative('.', path).replaceAll('\\', '/')] : [];
  });
}

it(`keeps every line of src and shaders within ${LIMIT} characters`, () => {
  const files = ['src', 'shaders'].flatMap(sources);
  expect(files.length).toBeGreaterThan(100);
  const long = files.flatMap((path) => readFileSync(path, 'utf8').split('\n')
    .flatMap((line, i) => ([...line].length > LIMIT ? [`${path}:${i + 1} (${[...line].length})`] : [])));
  expect(long).toEqual([]);
});
