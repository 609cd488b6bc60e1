// A tiny `#include <name>` mechanism for GLSL, in the style of three.js ShaderChunk:
// every program shares shaders/fresnel.glsl instead of pasting a copy of it.
// Pure (no DOM), so tests in Node assemble exactly what the browser compiles.

const INCLUDE = /^[ \t]*#include\s+<([\w.-]+)>[ \t]*$/gm;

/**
 * Replaces each `#include <name>` line with chunks[name], recursively.
 * Each chunk is included at most once per program; a missing chunk or a cycle throws.
 */
export function resolveIncludes(source, chunks, seen = new Set(), stack = []) {
  return source.replace(INCLUDE, (_line, name) => {
    if (stack.includes(name)) throw new Error(`GLSL include cycle: ${[...stack, name].join(' -> ')}`);
    if (!(name in chunks)) throw new Error(`GLSL include <${name}> not found`);
    if (seen.has(name)) return `// <${name}> already included`;
    seen.add(name);
    return resolveIncludes(chunks[name], chunks, seen, [...stack, name]);
  });
}
