// GPU twin check: every function of shaders/fresnel.glsl evaluated on the GPU into an RGBA32F
// target over a grid of (cos θ, n_i, n_t), read back, and compared with src/optics/fresnel.js.
import { readFileSync, readdirSync } from 'node:fs';
import { test, expect, openLab } from './fixtures.js';
import { readBack } from './readBack.js';
import { resolveIncludes } from '../../src/gl/resolveIncludes.js';
import * as optics from '../../src/optics/fresnel.js';
import { metals } from './metalsData.js';

const chunks = Object.fromEntries(readdirSync('shaders').filter((f) => f.endsWith('.glsl'))
  .map((f) => [f.replace(/\.glsl$/, ''), readFileSync(`shaders/${f}`, 'utf8')]));

// Each pass writes four results per pixel from the inputs (cos, nI, nT, k).
const PASSES = [
  ['fresnelExact(v.x, v.y, v.z)', 'fresnelSchlick(v.x, v.y, v.z)', 'fresnelSchlickTIR(v.x, v.y, v.z)', 'fresnelSchlickExp2(v.x, v.y, v.z)'],
  ['fresnelPolarized(v.x, v.y, v.z).x', 'fresnelPolarized(v.x, v.y, v.z).y', 'fresnelTransmittance(v.x, v.y, v.z).x', 'fresnelTransmittance(v.x, v.y, v.z).y'],
  ['fresnelConductor(v.x, v.y, v.w)', 'snellCosT(v.x, v.y, v.z)', 'normalIncidence(v.y, v.z)', 'brewsterAngle(v.y, v.z)'],
];
const twins = [
  [
    (c, a, b) => optics.fresnelExact(c, a, b), (c, a, b) => optics.fresnelSchlick(c, a, b),
    (c, a, b) => optics.fresnelSchlickTIR(c, a, b), (c, a, b) => optics.fresnelSchlickExp2(c, a, b),
  ],
  [
    (c, a, b) => optics.fresnelPolarized(c, a, b).s, (c, a, b) => optics.fresnelPolarized(c, a, b).p,
    (c, a, b) => optics.fresnelTransmittance(c, a, b).s, (c, a, b) => optics.fresnelTransmittance(c, a, b).p,
  ],
  [
    (c, a, _b, k) => optics.fresnelConductor(c, a, k), (c, a, b) => optics.snellCosT(c, a, b) ?? -1,
    (_c, a, b) => optics.normalIncidence(a, b), (_c, a, b) => optics.brewsterAngle(a, b),
  ],
];
const NAMES = PASSES.flat().map((s) => s.replace(/\(.*?\)/, '').replace('v.x, v.y, v.z', ''));

function fragmentShader(pass) {
  return resolveIncludes(`#version 300 es
precision highp float;
precision highp sampler2D;
#include <fresnel>
uniform sampler2D uInputs;
out vec4 outColor;
void main() {
  vec4 v = texelFetch(uInputs, ivec2(gl_FragCoord.xy), 0);
  outColor = vec4(${PASSES[pass].join(', ')});
}`, chunks);
}

// Within NEAR rad of a critical angle a value is compared by angle (see the test); outside it, to 2e-6.
const NEAR = 0.02;

// The grid: cos θ from 0 to 1 (ends, grazing, near 1), index pairs both ways, matched indices,
// and cosines bracketing each critical angle, inside NEAR and just outside it (1.25 and 2 × NEAR,
// where R still climbs steeply and float32 cancellation in cos θt is largest of the strict rows).
// Inputs are rounded to float32, as the GPU sees them.
const PAIRS = [[1, 1.5], [1.5, 1], [1, 1.333], [1.333, 1], [1, 2.417], [2.417, 1], [1.31, 1.333], [1.333, 1.31], [1.5, 1.5], [1, 1], [2.5, 1.2], [1.2, 2.5]];
function grid() {
  const cosines = [0, 1, 1e-6, 1e-4, 1e-3, 0.01, 0.05, 0.999, 0.99999, ...Array.from({ length: 48 }, (_, i) => (i + 0.5) / 48)];
  const rows = [];
  PAIRS.forEach(([nI, nT], j) => {
    const k = metals[j % metals.length].k[j % 3];
    const cs = [...cosines];
    const critical = optics.criticalAngle(nI, nT);
    if (critical !== null) for (const d of [-0.04, -0.025, -1e-2, -1e-3, -1e-5, 0, 1e-5, 1e-3, 1e-2, 0.025, 0.04]) cs.push(Math.cos(critical + d));
    for (const c of cs) rows.push([c, nI, nT, k].map(Math.fround));
  });
  for (const metal of metals) {
    for (let ch = 0; ch < 3; ch += 1) {
      for (const c of [0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 1]) rows.push([c, metal.n[ch], 1, metal.k[ch]].map(Math.fround));
    }
  }
  return rows;
}

test('every GLSL function matches its JS twin on the GPU (RGBA32F read-back)', async ({ page }) => {
  await openLab(page);
  const rows = grid();
  const width = 64;
  const results = await readBack(page, {
    width,
    height: Math.ceil(rows.length / width),
    textures: { uInputs: rows.flat() },
    runs: PASSES.map((_, i) => ({ fragment: fragmentShader(i) })),
  });

  const failures = [];
  let worst = 0;
  let nearCritical = 0;
  const strictBelow = new Set(); // pairs with a row held to 2e-6 between NEAR and 2.5 NEAR below θc
  results.forEach((out, pass) => {
    rows.forEach(([c, nI, nT, k], i) => {
      const critical = optics.criticalAngle(nI, nT);
      const theta = Math.acos(Math.min(1, c));
      for (let f = 0; f < 4; f += 1) {
        const name = NAMES[pass * 4 + f];
        const gpu = out[i * 4 + f];
        const js = twins[pass][f](c, nI, nT, k);
        const ranged = name.startsWith('snellCosT') || name.startsWith('brewster');
        if (!Number.isFinite(gpu)) { failures.push(`${name}(${c}, ${nI}, ${nT}, ${k}) is ${gpu}`); continue; }
        if (!ranged && (gpu < 0 || gpu > 1)) failures.push(`${name}(${c}, ${nI}, ${nT}) = ${gpu} is outside [0, 1]`);
        const error = Math.abs(gpu - js);
        // Near the critical angle R is ill-conditioned (dR/dcos reaches -1600 at 1e-5 above it),
        // and float32 inputs alone move R by more than 2e-6. Within 0.02 rad of it, compare by
        // angle: the GPU value must be the JS value at some angle within 1e-5 rad.
        const dependsOnAngle = pass < 2 || name.startsWith('snellCosT');
        if (critical !== null && dependsOnAngle && Math.abs(theta - critical) < NEAR) {
          const near = [-1e-5, 0, 1e-5].map((d) => twins[pass][f](Math.cos(Math.max(0, theta + d)), nI, nT, k));
          if (gpu < Math.min(...near) - 2e-6 || gpu > Math.max(...near) + 2e-6) {
            failures.push(`${name}(${c}, ${nI}, ${nT}) near θc: gpu ${gpu} outside JS [${Math.min(...near)}, ${Math.max(...near)}]`);
          }
          nearCritical += 1;
          continue;
        }
        worst = Math.max(worst, error);
        if (critical !== null && dependsOnAngle && critical - theta < 2.5 * NEAR && critical - theta >= NEAR) strictBelow.add(`${nI} → ${nT}`);
        if (error > 2e-6) failures.push(`${name}(${c}, ${nI}, ${nT}, ${k}): gpu ${gpu} js ${js} error ${error.toExponential(2)}`);
      }
    });
  });
  console.log(`[gpu twin] ${rows.length} inputs x ${NAMES.length} functions, worst |gpu - js| = ${worst.toExponential(2)} (${nearCritical} values near θc compared by angle)`);
  expect(failures.slice(0, 20)).toEqual([]);
  const withCritical = PAIRS.filter(([nI, nT]) => nI > nT).map((pair) => pair.map(Math.fround).join(' → '));
  expect([...strictBelow].sort(), 'every pair with a critical angle has rows just outside NEAR held to 2e-6').toEqual(withCritical.sort());
});
