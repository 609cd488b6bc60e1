// GPU twin check of shaders/microfacet.glsl: every function it defines (ggxDistribution,
// smithLambda, smithG2, microfacetSpecular) evaluated on the GPU into an RGBA32F target over a grid
// of (cosL, cosV, cosH, α, F), read back, and compared with src/optics/microfacet.js, in the style
// of gpuTwin.spec.js and normalMapsTwin.spec.js.
import { readFileSync, readdirSync } from 'node:fs';
import { test, expect, openLab } from './fixtures.js';
import { readBack } from './readBack.js';
import { resolveIncludes } from '../../src/gl/resolveIncludes.js';
import * as mf from '../../src/optics/microfacet.js';

const chunks = Object.fromEntries(readdirSync('shaders').filter((f) => f.endsWith('.glsl'))
  .map((f) => [f.replace(/\.glsl$/, ''), readFileSync(`shaders/${f}`, 'utf8')]));
const F32 = Math.fround;

// One pixel per grid row: v = (cosL, cosV, cosH, α) from one texture and F from another; four results.
const RIGHT = ['ggxDistribution(v.z, v.w)', 'smithLambda(v.x, v.w)', 'smithG2(v.x, v.y, v.w)', 'microfacetSpecular(v.x, v.y, v.z, v.w, f)'];
// Deliberately wrong: α swapped with a cosine in every call. The comparison must see it.
const WRONG = ['ggxDistribution(v.w, v.z)', 'smithLambda(v.w, v.x)', 'smithG2(v.x, v.w, v.y)', 'microfacetSpecular(v.x, v.y, v.w, v.z, f)'];
const NAMES = RIGHT.map((call) => call.slice(0, call.indexOf('(')));

function fragmentShader(calls) {
  return resolveIncludes(`#version 300 es
precision highp float;
precision highp sampler2D;
#include <microfacet>
uniform sampler2D uArgs;
uniform sampler2D uF;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 v = texelFetch(uArgs, p, 0);
  float f = texelFetch(uF, p, 0).x;
  outColor = vec4(${calls.join(', ')});
}`, chunks);
}

// The grid, in float32 as the GPU sees it: cosines below the surface, 0, 1e-7, grazing, near 1, 1
// and 1 + 1 ulp (interpolated normals overshoot); α from 1e-4 (the GGX peak is 1/(πα²) ≈ 3e7)
// through the panel's 0.04 (roughness 0.2) to 1; F outside [0, 1].
const COS = [-1, -0.5, -1e-3, -1e-6, 0, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5,
  0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 0.999, 0.9999, 0.99999, 1 - 2 ** -24, 1, 1 + 2 ** -23].map(F32);
const ALPHA = [1e-4, 1e-3, 2e-3, 5e-3, 0.01, 0.02, 0.04, 0.1, 0.2, 0.3, 0.5, 0.64, 0.8, 0.9, 0.99, 1].map(F32);
const PANEL_ALPHA = F32(0.04); // the asphalt panel's smallest α (roughness 0.2, α = r²)
const FS = [-0.5, -1e-3, 0, 0.04, 0.3, 1, 1.001, 2].map(F32);

// Every (cosL, cosV, α); cosH cycles so that every (cosH, α) pair occurs too.
function grid() {
  const rows = [];
  COS.forEach((cosL, i) => COS.forEach((cosV, j) => ALPHA.forEach((alpha, k) => {
    rows.push({ cosL, cosV, cosH: COS[(i + 2 * j) % COS.length], alpha, F: FS[(i + j + k) % FS.length] });
  })));
  return rows;
}

const clamp01 = (x) => Math.min(1, Math.max(0, x));

function jsValues(r) {
  return [mf.ggxDistribution(r.cosH, r.alpha), mf.smithLambda(r.cosL, r.alpha), mf.smithG2(r.cosL, r.cosV, r.alpha),
    mf.microfacetSpecular(r)];
}

// The allowed error is a running error bound (Higham, "Accuracy and Stability of Numerical
// Algorithms", 2nd ed., §3.3) of the GLSL's own operations in its own order: each value carries
// its exact value v and a bound e on |float32 − v|. With u = 2^-24, +, − and × are correctly
// rounded (|error| ≤ u|v|); ÷ may be off by 2.5 ulp (5u|v|) and sqrt, "inherited from
// 1/inversesqrt" (2 ulp, then a 2.5 ulp division), by 9u|v|: the Vulkan precision rules that
// ANGLE's backend here follows (Vulkan spec, "Precision and Operation of SPIR-V Instructions"; the
// GLSL 4.x table is the same). So the tolerance is relative in form and tight where nothing
// cancels (a few 1e-7 of G2), and wide only where float32 itself cannot do better (Λ near c = 1,
// where √(…)/c − 1 keeps about one ulp of 1).
const U = 2 ** -24;
const V = (v, e = 0) => ({ v, e });
const add = (a, b) => { const v = a.v + b.v; return V(v, a.e + b.e + U * Math.abs(v)); };
const sub = (a, b) => add(a, V(-b.v, b.e));
const mul = (a, b) => {
  const v = a.v * b.v;
  return V(v, Math.abs(a.v) * b.e + Math.abs(b.v) * a.e + a.e * b.e + U * Math.abs(v));
};
const div = (a, b) => {
  const v = a.v / b.v;
  const low = Math.abs(b.v) - b.e;
  return V(v, low > 0 ? (a.e + Math.abs(v) * b.e) / low + 5 * U * Math.abs(v) : Infinity);
};
const sqrt = (a) => {
  const v = Math.sqrt(a.v);
  return V(v, a.e / (v + Math.sqrt(Math.max(0, a.v - a.e))) + 9 * U * v);
};
const ONE = V(1);
const PI = V(Math.PI, Math.abs(F32(3.14159265358979) - Math.PI)); // MF_PI as float32

function modelD(cosH, a) {
  const c = V(clamp01(cosH));
  const a2 = mul(a, a);
  const d = add(mul(sub(ONE, c), add(ONE, c)), mul(mul(c, c), a2));
  return div(a2, mul(mul(PI, d), d));
}
function modelLambda(cos, a) {
  const c = V(clamp01(cos));
  if (c.v === 0) return V(Infinity);
  const s = sqrt(add(mul(c, c), mul(mul(a, a), mul(sub(ONE, c), add(ONE, c)))));
  return mul(V(0.5), sub(div(s, c), ONE));
}
function model(r) {
  const a = V(r.alpha);
  const D = modelD(r.cosH, a);
  const above = r.cosL > 0 && r.cosV > 0;
  const G = above ? div(ONE, add(add(ONE, modelLambda(r.cosL, a)), modelLambda(r.cosV, a))) : V(0);
  const spec = above
    ? div(mul(mul(D, G), V(clamp01(r.F))), mul(mul(V(4), V(Math.min(1, r.cosL))), V(Math.min(1, r.cosV)))) : V(0);
  return [D, modelLambda(r.cosL, a), G, spec];
}

// Inputs as two RGBA32F textures, (cosL, cosV, cosH, α) and (F, 0, 0, 0): one texel per grid row.
function render(page, rows, shaders) {
  const width = 128;
  return readBack(page, {
    width,
    height: Math.ceil(rows.length / width),
    textures: { uArgs: rows.flatMap((r) => [r.cosL, r.cosV, r.cosH, r.alpha]), uF: rows.flatMap((r) => [r.F, 0, 0, 0]) },
    runs: shaders.map((fragment) => ({ fragment })),
  });
}

const fmt = (r) => `(cosL ${r.cosL}, cosV ${r.cosV}, cosH ${r.cosH}, α ${r.alpha}, F ${r.F})`;

test('every function of microfacet.glsl matches its JS twin on the GPU (RGBA32F read-back)', async ({ page }) => {
  // Every function the chunk defines is checked here, and each has a JS twin of the same name.
  const defined = [...chunks.microfacet.matchAll(/^\s*(?:float|vec[234]|int|bool)\s+(\w+)\s*\(/gm)].map((m) => m[1]);
  expect(defined.sort()).toEqual([...NAMES].sort());
  for (const name of NAMES) expect(typeof mf[name]).toBe('function');

  // A light panel without WebGL, so the page holds no other context while the twin renders.
  await openLab(page, './embed.html?panel=r0-derivation');
  const rows = grid();
  const [right, wrong] = await render(page, rows, [fragmentShader(RIGHT), fragmentShader(WRONG)]);

  const failures = [];
  const worst = () => ({ value: 0, at: '-' });
  const raise = (w, value, at) => { if (value > w.value) { w.value = value; w.at = at; } };
  const stats = NAMES.map(() => ({ rel: worst(), relPanel: worst(), abs: worst(), used: worst(), wrongSeen: 0, wrongOf: 0 }));
  rows.forEach((r, i) => {
    const js = jsValues(r);
    const bounds = model(r);
    for (let f = 0; f < NAMES.length; f += 1) {
      const name = NAMES[f];
      const gpu = right[i * 4 + f];
      const { v, e } = bounds[f];
      // The model must be the same formula as the JS (else its bound would be about something else).
      if (!(v === js[f] || Math.abs(v - js[f]) <= 1e-12 * Math.abs(js[f]))) failures.push(`model ${name}${fmt(r)} = ${v}, JS ${js[f]}`);
      // Λ at grazing is +Infinity in both twins; nothing else may be infinite or NaN.
      if (js[f] === Infinity) { if (gpu !== Infinity) failures.push(`${name}${fmt(r)} is ${gpu} on the GPU, JS Infinity`); continue; }
      if (!Number.isFinite(gpu)) { failures.push(`${name}${fmt(r)} is ${gpu} on the GPU (JS ${js[f]})`); continue; }
      const error = Math.abs(gpu - js[f]);
      const s = stats[f];
      const at = `${fmt(r)}: gpu ${gpu} js ${js[f]}`;
      if (js[f] !== 0) raise(s.rel, error / Math.abs(js[f]), at);
      if (js[f] !== 0 && r.alpha >= PANEL_ALPHA) raise(s.relPanel, error / Math.abs(js[f]), at);
      raise(s.abs, error, at);
      if (e > 0) raise(s.used, error / e, at);
      if (!(error <= e)) failures.push(`${name}${fmt(r)}: gpu ${gpu} js ${js[f]} error ${error.toExponential(2)} > bound ${e.toExponential(2)}`);
      if (name === 'smithG2' && (gpu < 0 || gpu > 1)) failures.push(`${name}${fmt(r)} = ${gpu} is outside [0, 1]`);
      if (name !== 'smithLambda' && gpu < 0) failures.push(`${name}${fmt(r)} = ${gpu} < 0`);
      // Deliberately wrong arguments, judged by the same bound.
      const bad = wrong[i * 4 + f];
      if (js[f] !== 0) {
        s.wrongOf += 1;
        if (!Number.isFinite(bad) || !(Math.abs(bad - js[f]) <= e)) s.wrongSeen += 1;
      }
    }
  });

  NAMES.forEach((name, f) => {
    const s = stats[f];
    console.log(`[microfacet twin] ${name}: worst |gpu − js|/|js| ${s.rel.value.toExponential(2)} at ${s.rel.at}; `
      + `for α ≥ 0.04 ${s.relPanel.value.toExponential(2)} at ${s.relPanel.at}; `
      + `worst |gpu − js| ${s.abs.value.toExponential(2)} at ${s.abs.at}; at most ${(100 * s.used.value).toFixed(1)}% of the `
      + `allowed error, at ${s.used.at}; swapped α noticed in ${s.wrongSeen} of ${s.wrongOf} nonzero values`);
    // α swapped with a cosine leaves only the few rows where they are (nearly) equal in agreement.
    if (!(s.wrongSeen > 0.9 * s.wrongOf)) failures.push(`${name} with α and a cosine swapped went unnoticed in ${s.wrongOf - s.wrongSeen} rows`);
  });
  console.log(`[microfacet twin] ${rows.length} inputs x ${NAMES.length} functions`);
  expect(failures.slice(0, 20)).toEqual([]);
});
