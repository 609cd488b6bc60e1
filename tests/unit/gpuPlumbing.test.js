// The page compiles shaders in one place: src/gl/compileProgram.js compiles and links every program
// with the one full-screen vertex shader, and src/gl/shaderError.js holds the one error a refused
// shader throws. A caller that compiles on its own again, writes another full-screen vertex shader
// or another shader error class fails here.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOTS = ['src', 'shaders'];
const PLUMBING = 'src/gl/compileProgram.js';
const ERROR_MODULE = 'src/gl/shaderError.js';

function sources(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sources(path);
    return /\.(js|mjs|glsl|vert|frag)$/.test(entry.name) ? [relative('.', path).replaceAll('\\', '/')] : [];
  });
}

const files = ROOTS.flatMap(sources).map((path) => ({ path, text: readFileSync(path, 'utf8') }));

/** The files other than `allowed` whose text matches `pattern`. */
const offenders = (pattern, allowed) => files.filter((f) => f.path !== allowed && pattern.test(f.text)).map((f) => f.path);

describe('one GPU plumbing', () => {
  it('finds the sources it checks', () => {
    expect(files.map((f) => f.path)).toContain(PLUMBING);
    expect(files.length).toBeGreaterThan(50);
  });

  it('compiles, links and reads info logs only in compileProgram.js', () => {
    const calls = /\.(createShader|shaderSource|compileShader|linkProgram|getShaderInfoLog|getProgramInfoLog)\s*\(/;
    expect(offenders(calls, PLUMBING)).toEqual([]);
  });

  it('has one full-screen vertex shader (gl_VertexID appears only in compileProgram.js)', () => {
    expect(offenders(/gl_VertexID/, PLUMBING)).toEqual([]);
    expect(readFileSync(PLUMBING, 'utf8').match(/gl_Position\s*=/g)).toHaveLength(1);
  });

  it('has one error class for a refused shader, in shaderError.js', () => {
    expect(offenders(/class\s+\w*Shader\w*\s+extends\b/, ERROR_MODULE)).toEqual([]);
    expect(offenders(/\bShaderCompileFailed\b/, null)).toEqual([]);
    expect(readFileSync(ERROR_MODULE, 'utf8')).toMatch(/export class ShaderError extends Error/);
  });
});
