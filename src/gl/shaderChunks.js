// The shared GLSL chunks: every file in shaders/ as a chunk named after the file without `.glsl`,
// bundled as text. A panel's own shaders live in its folder and are imported as text (`?raw`);
// assembleShader resolves their `#include <name>` lines against these chunks.
import { resolveIncludes } from './resolveIncludes.js';

const files = import.meta.glob('../../shaders/*.glsl', { query: '?raw', import: 'default', eager: true });

export const shaderChunks = Object.fromEntries(
  Object.entries(files).map(([path, text]) => [path.split('/').pop().replace(/\.glsl$/, ''), text]),
);

/** GLSL source with its includes resolved: the shared chunks, plus a panel's own `extra` chunks. */
export function assembleShader(source, extra = {}) {
  return resolveIncludes(source, { ...shaderChunks, ...extra });
}
