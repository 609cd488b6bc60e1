// GPU twin check of shaders/normalMaps.glsl: mapSlope(uv) evaluated on the GPU into an
// RGBA32F target for every map kind (uniforms from src/normals/mapUniforms.js), read back and
// compared with the JS map's slopeAt(u, v) (src/normals/), in the style of gpuTwin.spec.js.
import { readFileSync, readdirSync } from 'node:fs';
import { test, expect, openLab } from './fixtures.js';
import { readBack } from './readBack.js';
import { resolveIncludes } from '../../src/gl/resolveIncludes.js';
import { createNormalMap } from '../../src/normals/createNormalMap.js';
import { mapUniforms } from '../../src/normals/mapUniforms.js';

const chunks = Object.fromEntries(readdirSync('shaders').filter((f) => f.endsWith('.glsl'))
  .map((f) => [f.replace(/\.glsl$/, ''), readFileSync(`shaders/${f}`, 'utf8')]));

const FRAGMENT = resolveIncludes(`#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
#include <normalMaps>
uniform sampler2D uInputs;
out vec4 outColor;
void main() {
  vec4 v = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0);
  outColor = vec4(mapSlope(v.xy), 0.0, 1.0);
}`, chunks);

const SIZE = 64; // 4096 points per map
const RAD = 180 / Math.PI;
const CASES = [
  ['bumps', {}],
  ['bumps', { frequency: 5, edgeAngleDeg: 70 }],
  ['grooves', {}],
  ['grooves', { frequency: 6, angleDeg: 35, profile: 'sine', direction: 'v' }],
  ['grooves', { frequency: 3, angleDeg: 50, direction: 'diagonal' }],
  ['checker', {}],
  ['checker', { frequency: 6, angleDeg: 40 }],
  ['noise', {}],
  ['noise', { frequency: 3, octaves: 6, gain: 0.7, amplitude: 0.3, seed: -123456789 }],
  ['noise', { frequency: 16, octaves: 1, amplitude: 0.05, seed: 0x9e3779b9 }], // a seed above 2^31
  ['mixed', {}],
  ['mixed', { blocks: 5, frequency: 1, angleDeg: 30, edgeAngleDeg: 60, amplitude: 0.2, seed: 77 }],
  ['mixed', { blocks: 3, frequency: 3, angleDeg: 10, edgeAngleDeg: 20, seed: -5 }],
  ['flat', {}],
].map(([kind, params]) => ({ name: `${kind} ${JSON.stringify(params)}`, map: createNormalMap(kind, params) }));
// Deliberately wrong uniforms: the comparison must see them (the test can fail).
const WRONG = [
  { name: 'noise, seed + 1', map: CASES[7].map, change: (u) => ({ ...u, uNoiseSeed: u.uNoiseSeed + 1 }) },
  { name: 'mixed, 3 blocks instead of 4', map: CASES[10].map, change: (u) => ({ ...u, uMixedBlocks: 3 }) },
  { name: 'grooves sine as v', map: CASES[3].map, change: (u) => ({ ...u, uGrooveProfile: 0 }) },
  { name: 'bump edge angle 0.3° steeper', map: CASES[0].map, change: (u) => ({ ...u, uMapAngle: u.uMapAngle + 0.3 / RAD }) },
  { name: 'mixed facet angle 0.3° steeper', map: CASES[10].map, change: (u) => ({ ...u, uMapAngle: u.uMapAngle + 0.3 / RAD }) },
];

// Float32 points of an R2 low-discrepancy sequence over [−0.5, 1.5)², so the period wrap is used.
function points() {
  const g = 1.324717957244746; // the plastic number (Roberts, "The unreasonable effectiveness of quasirandom sequences")
  return Array.from({ length: SIZE * SIZE }, (_, i) => [
    Math.fround(((0.5 + i / g) % 1) * 2 - 0.5), Math.fround(((0.5 + i / (g * g)) % 1) * 2 - 0.5),
  ]);
}

// A point is skipped when the JS map itself jumps within DELTA of it (a second difference over
// ±DELTA along u, v or a diagonal above 1e-2; smooth fields, even the rim of a 70° cap, stay
// below 1e-3): cell, region and block borders, groove creases, bump rims, checker steps. There
// float32 rounding of uv·frequency in the shader (~1e-7 relative) may put the GPU on the other side.
const DELTA = 1e-4;
const DIRECTIONS = [[1, 0], [0, 1], [1, 1], [1, -1]];
function nearJump(map, u, v, s0) {
  const p = [0, 0];
  const m = [0, 0];
  return DIRECTIONS.some(([du, dv]) => {
    map.slopeAt(u + du * DELTA, v + dv * DELTA, p);
    map.slopeAt(u - du * DELTA, v - dv * DELTA, m);
    return Math.abs(p[0] - 2 * s0[0] + m[0]) > 1e-2 || Math.abs(p[1] - 2 * s0[1] + m[1]) > 1e-2;
  });
}

// The GPU's sin, cos and tan are not correctly rounded: GLSL ES 3.00 leaves their precision to the
// implementation, and Vulkan (ANGLE's backend here) allows 2^-11 absolute error for sin and cos in
// [−π, π] (Vulkan spec, "Precision and Operation of SPIR-V Instructions"); SwiftShader's are off
// by up to 1.9e-4. So a map that uses trig is compared by angle, as gpuTwin.spec.js does near θc:
// the GPU value must lie between the JS values at θ − Δ, θ and θ + Δ (the slopes are monotonic in
// θ at a fixed uv), Δ being the angle error that ε = 2^-11 on sin θm amounts to (bumps:
// Δ = ε / cos θm) or on sin and cos inside tan θ (Δ = √2 ε). Sine grooves also evaluate cos(2πt)
// per point: ε·tan θ more. Beyond that, float32 arithmetic (relative 6e-8 per step) is allowed
// FLOAT32·(1 + |b|) (the trig-free noise measures 3.5e-6 at most).
const EPS_TRIG = 2 ** -11;
const FLOAT32 = 1e-5;

function bracket(map) {
  const p = map.params;
  const shifted = (sign) => {
    const q = { ...p };
    if ('angleDeg' in p) q.angleDeg = Math.min(80, Math.max(0, p.angleDeg + sign * Math.SQRT2 * EPS_TRIG * RAD));
    if ('edgeAngleDeg' in p) {
      const d = (EPS_TRIG / Math.cos(p.edgeAngleDeg / RAD)) * RAD;
      q.edgeAngleDeg = Math.min(85, Math.max(1, p.edgeAngleDeg + sign * d));
    }
    return createNormalMap(map.kind, q);
  };
  const perPointCos = p.profile === 'sine' ? EPS_TRIG * Math.tan(p.angleDeg / RAD) : 0;
  return { lo: shifted(-1), hi: shifted(1), perPointCos };
}

// The worst raw |GPU − JS| over both components, and the worst excess beyond the allowed error.
function compare(map, pts, out) {
  const { lo, hi, perPointCos } = bracket(map);
  const a = [0, 0];
  const b = [0, 0];
  let worst = 0;
  let used = 0;
  let excess = 0;
  let skipped = 0;
  let where = null;
  pts.forEach(([u, v], i) => {
    const js = map.slopeAt(u, v, [0, 0]);
    if (nearJump(map, u, v, js)) { skipped += 1; return; }
    lo.slopeAt(u, v, a);
    hi.slopeAt(u, v, b);
    for (let c = 0; c < 2; c += 1) {
      const gpu = out[i * 4 + c];
      const tol = FLOAT32 * (1 + Math.abs(js[c])) + perPointCos;
      const over = Number.isFinite(gpu) ? Math.max(Math.min(a[c], b[c], js[c]) - tol - gpu, gpu - Math.max(a[c], b[c], js[c]) - tol, 0) : Infinity;
      worst = Math.max(worst, Math.abs(gpu - js[c]));
      used = Math.max(used, Math.abs(gpu - js[c]) / (Math.max(Math.abs(a[c] - js[c]), Math.abs(b[c] - js[c])) + tol));
      if (over > excess) { excess = over; where = { u, v, gpu: [out[i * 4], out[i * 4 + 1]], js }; }
    }
  });
  return { worst, used, excess, skipped, where };
}

test('mapSlope of every map kind matches its JS twin on the GPU (RGBA32F read-back)', async ({ page }) => {
  // A light panel without WebGL, so the page holds no other context while the twin renders.
  await openLab(page, './embed.html?panel=r0-derivation');
  const pts = points();
  const runs = [...CASES.map((c) => mapUniforms(c.map)), ...WRONG.map((w) => w.change(mapUniforms(w.map)))];
  const results = await readBack(page, {
    width: SIZE,
    height: SIZE,
    textures: { uInputs: pts.flatMap(([u, v]) => [u, v, 0, 0]) },
    runs: runs.map((uniforms) => ({ fragment: FRAGMENT, uniforms })),
  });

  const failures = [];
  CASES.forEach(({ name, map }, c) => {
    const { worst, used, excess, skipped, where } = compare(map, pts, results[c]);
    console.log(`[maps twin] ${name}: worst |gpu - js| = ${worst.toExponential(2)} (${(100 * used).toFixed(0)}% of the allowed error), `
      + `${skipped} of ${pts.length} points near a jump skipped`);
    if (excess > 0) failures.push(`${name}: ${excess} beyond the allowed error at ${JSON.stringify(where)}`);
    // Jumps are lines: a band of ±1e-4 around them must stay a small share of the points.
    if (skipped > 0.05 * pts.length) failures.push(`${name}: ${skipped} points skipped`);
  });
  WRONG.forEach(({ name, map }, w) => {
    const { worst, excess } = compare(map, pts, results[CASES.length + w]);
    console.log(`[maps twin] deliberately wrong (${name}): worst |gpu - js| = ${worst.toExponential(2)}, ${excess.toExponential(2)} beyond the allowed error`);
    if (!(excess > 1e-3)) failures.push(`deliberately wrong uniforms (${name}) went unnoticed: ${excess} beyond the allowed error`);
  });
  expect(failures).toEqual([]);
});
