// Every file in shaders/ as a chunk named after the file without `.glsl`, bundled as text.
import { resolveIncludes } from './resolveIncludes.js';

const files = import.meta.glob('../../shaders/*.glsl', { query: '?raw', import: 'default', eager: true });

export const shaderChunks = Object.fromEntries(
  Object.entries(files).map(([path, text]) => [path.split('/').pop().replace(/\.glsl$/, ''), text]),
);

/** The named shader file with its includes resolved. */
export function shaderSource(name) {
  if (!(name in shaderChunks)) throw new Error(`no shader named ${name}`);
  return resolveIncludes(shaderChunks[name], shaderChunks);
}
