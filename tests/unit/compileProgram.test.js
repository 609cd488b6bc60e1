// compileProgram and the full-screen triangle against a stand-in for WebGL2 that records calls and
// refuses what a test tells it to: the order of checks, what a ShaderError holds, what is deleted.
import { describe, expect, it } from 'vitest';
import { checkProgram, compileProgram, createFullScreenTriangle, FULL_SCREEN_VERTEX } from '../../src/gl/compileProgram.js';
import { ShaderError } from '../../src/gl/shaderError.js';

/** refuse: { vertex?, fragment?, link? } → the log of that failure; lost: the context is lost. */
function fakeGl({ refuse = {}, lost = false } = {}) {
  const calls = [];
  const gl = {
    VERTEX_SHADER: 0x8b31, FRAGMENT_SHADER: 0x8b30, COMPILE_STATUS: 0x8b81, LINK_STATUS: 0x8b82, TRIANGLES: 4,
    calls,
    isContextLost: () => lost,
    createProgram: () => ({ kind: 'program', shaders: [] }),
    createShader: (type) => ({ kind: 'shader', stage: type === 0x8b31 ? 'vertex' : 'fragment' }),
    shaderSource: (shader, source) => { shader.source = source; },
    compileShader: (shader) => calls.push(`compile ${shader.stage}`),
    attachShader: (program, shader) => program.shaders.push(shader),
    linkProgram: () => calls.push('link'),
    deleteShader: (shader) => calls.push(`delete ${shader.stage}`),
    deleteProgram: () => calls.push('delete program'),
    getShaderParameter: (shader) => (lost ? null : !(shader.stage in refuse)),
    getShaderInfoLog: (shader) => refuse[shader.stage] ?? '',
    getProgramParameter: () => (lost ? null : !('link' in refuse) && !('vertex' in refuse) && !('fragment' in refuse)),
    getProgramInfoLog: () => refuse.link ?? 'a stage did not compile',
    createVertexArray: () => ({ kind: 'vao' }),
    bindVertexArray: (vao) => calls.push(vao ? 'bind vao' : 'bind null'),
    drawArrays: (mode, first, count) => calls.push(`draw ${mode} ${first} ${count}`),
    deleteVertexArray: () => calls.push('delete vao'),
  };
  return gl;
}

const FRAGMENT = '#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = vec4(y); }';

describe('compileProgram', () => {
  it('compiles the full-screen vertex shader with the fragment, links, and flags both shaders for deletion', () => {
    const gl = fakeGl();
    const program = compileProgram(gl, FRAGMENT);
    expect(program.shaders.map((s) => [s.stage, s.source])).toEqual([['vertex', FULL_SCREEN_VERTEX], ['fragment', FRAGMENT]]);
    expect(gl.calls).toEqual(['compile vertex', 'compile fragment', 'link', 'delete vertex', 'delete fragment']);
  });

  it('throws ShaderError with the stage, the log, the source and the line it names, and deletes the program', () => {
    const gl = fakeGl({ refuse: { fragment: "ERROR: 0:4: 'y' : undeclared identifier" } });
    let error = null;
    try { compileProgram(gl, FRAGMENT); } catch (e) { error = e; }
    expect(error).toBeInstanceOf(ShaderError);
    expect(error.stage).toBe('fragment');
    expect(error.log).toBe("ERROR: 0:4: 'y' : undeclared identifier");
    expect(error.source).toBe(FRAGMENT);
    expect(error.message).toBe("The fragment shader did not compile:\nERROR: 0:4: 'y' : undeclared identifier\n    4: void main() { c = vec4(y); }");
    expect(gl.calls.at(-1)).toBe('delete program');
  });

  it('reports the vertex stage first when both are refused, as a driver refusing everything does', () => {
    const gl = fakeGl({ refuse: { vertex: 'ERROR: 0:1: no', fragment: 'ERROR: 0:1: no' } });
    expect(() => compileProgram(gl, FRAGMENT)).toThrow(/^The vertex shader did not compile:\nERROR: 0:1: no\n {4}1: #version 300 es$/);
  });

  it('reports a failed link with the program\'s log, named by the label', () => {
    const gl = fakeGl({ refuse: { link: 'Too many varyings.' } });
    expect(() => compileProgram(gl, FRAGMENT, { label: 'the probe' })).toThrow(expect.objectContaining({
      stage: 'link', log: 'Too many varyings.', message: 'The shader program (the probe) did not link:\nToo many varyings.',
    }));
  });

  it('throws nothing on a lost context (every status reads as failed there)', () => {
    const gl = fakeGl({ lost: true });
    expect(compileProgram(gl, FRAGMENT)).toBeTruthy();
  });

  it('with check: false returns the program unchecked; checkProgram throws later', () => {
    const gl = fakeGl({ refuse: { fragment: 'ERROR: 0:2: late' } });
    const programs = [compileProgram(gl, FRAGMENT, { check: false }), compileProgram(gl, FRAGMENT, { check: false })];
    expect(gl.calls.filter((c) => c === 'link')).toHaveLength(2);
    expect(() => checkProgram(gl, programs[1], { label: 'timing fresnel, mediump' }))
      .toThrow('The fragment shader (timing fresnel, mediump) did not compile:\nERROR: 0:2: late\n    2: precision highp float;');
    expect(gl.calls).not.toContain('delete program'); // the caller owns an unchecked program
  });
});

describe('the full-screen triangle', () => {
  it('is one triangle from gl_VertexID whose inside holds the whole viewport, with vUv 0..1 across it', () => {
    // The vertex shader's arithmetic, line for line.
    expect(FULL_SCREEN_VERTEX).toContain('vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);');
    expect(FULL_SCREEN_VERTEX).toContain('vUv = p * 0.5 + 0.5;');
    const corners = [0, 1, 2].map((id) => [((id & 1) << 2) - 1, ((id & 2) << 1) - 1]);
    expect(corners).toEqual([[-1, -1], [3, -1], [-1, 3]]);
    // Inside x ≥ -1, y ≥ -1, x + y ≤ 2: each corner of the clip square [-1, 1]² is.
    for (const [x, y] of [[-1, -1], [1, -1], [-1, 1], [1, 1]]) expect(x >= -1 && y >= -1 && x + y <= 2).toBe(true);
    // Counter-clockwise (positive area), so face culling set to the default back face keeps it.
    const [[ax, ay], [bx, by], [cx, cy]] = corners;
    expect((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)).toBeGreaterThan(0);
  });

  it('draws three vertices from its own empty vertex array, and unbinds it', () => {
    const gl = fakeGl();
    const triangle = createFullScreenTriangle(gl);
    triangle.draw();
    triangle.dispose();
    expect(gl.calls).toEqual(['bind vao', 'draw 4 0 3', 'bind null', 'delete vao']);
  });
});
