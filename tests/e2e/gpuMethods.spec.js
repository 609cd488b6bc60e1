// GPU twins of the Fresnel methods: every method of shaders/fresnelMethods.glsl, evaluated through
// evaluateMethodsGpu (RGBA32F render, FLOAT read-back) on the stability panel's own context, must
// match its JS twin (src/methods/methods.js) in float32, and give NaN exactly where the JS does.
import { test, expect, openLab } from './fixtures.js';
import { criticalAngle, conductorNormalIncidence } from '../../src/optics/fresnel.js';
import { METHOD_IDS, methodById } from '../../src/methods/methods.js';
import { METHOD_INDEX } from '../../src/gl/methodIndex.js';
import { metals } from './metalsData.js';

const f = Math.fround;
// Within NEAR rad of a critical angle a value is compared by angle (see compare); outside it, to 2e-6.
const NEAR = 0.02;
const PAIRS = [[1, 1.5], [1.5, 1], [1, 1.333], [1.333, 1], [2.417, 1], [1.31, 1.333], [1.333, 1.31], [1, 1], [1.5, 1.5], [0.4, 1], [2.5, 1]];

// Dielectric rows (cos, nI, nT, 0): index pairs both ways, matched media, grazing and normal
// incidence, cosines bracketing each critical angle (inside NEAR, and just outside it at 1.25 and
// 2 × NEAR, where R still climbs steeply), the out-of-range cosines that interpolated or
// normal-mapped normals produce (an overshoot past 1, where pow(1 − c, 5) has a negative base, and
// a negative cosine), and
// NaN and Infinity inputs, which must come back through the RGBA32F read-back as NaN / ±Infinity.
function dielectricRows() {
  const cosines = [0, 1, 1e-6, 1e-4, 1e-3, 0.01, 0.05, 0.999, 0.99999, ...Array.from({ length: 40 }, (_, i) => (i + 0.5) / 40)];
  const rows = [];
  for (const [nI, nT] of PAIRS) {
    const cs = [...cosines, 1 + 2 ** -23, 1.001, -0.05, NaN, Infinity];
    const critical = criticalAngle(nI, nT);
    if (critical !== null) for (const d of [-0.04, -0.025, -1e-2, -1e-3, -1e-5, 0, 1e-5, 1e-3, 1e-2, 0.025, 0.04]) cs.push(Math.cos(critical + d));
    for (const c of cs) rows.push([f(c), f(nI), f(nT), 0]);
  }
  return rows;
}

// Conductor rows (cos, n, k, f0) for every metal and channel of materials.json.
function conductorRows() {
  const rows = [];
  for (const metal of metals) {
    for (let ch = 0; ch < 3; ch += 1) {
      const [n, k] = [f(metal.n[ch]), f(metal.k[ch])];
      for (const c of [0, 1e-3, 0.01, 0.1, 1 / 7, 0.3, 0.5, 0.7, 0.9, 0.999, 1, NaN]) rows.push([f(c), n, k, f(conductorNormalIncidence(n, k))]);
    }
  }
  return rows;
}

async function gpuEvaluate(page, jobs) {
  return page.evaluate((list) => {
    const { gpu } = window.fresnelLab.panels.stability;
    return list.map(({ methodId, precision, rows }) => Array.from(gpu.evaluate({ methodId, precision, inputs: new Float32Array(rows.flat()) })));
  }, jobs);
}

/**
 * Where GLSL ES 3.00 leaves the result undefined (§8.2: pow(x, y) for x < 0; built-ins fed a NaN,
 * as NaNs need not be supported, §4.5.1), so a GPU may differ from the JS model (NaN) without a
 * bug: pow(1 − c, 5) for c > 1 (SwiftShader returns pow(|x|, 5)), and a NaN input reaching pow or
 * clamp (SwiftShader: pow(NaN, 5) = Infinity). Plain arithmetic, sqrt and comparisons must still
 * propagate NaN as IEEE 754 does.
 */
function undefinedInGlsl(methodId, [c]) {
  const builtin = ['schlick-pow', 'schlick-exp2', 'conductor-f82'].includes(methodId);
  return (methodId === 'schlick-pow' && c > 1) || (Number.isNaN(c) && builtin);
}

/**
 * |gpu − js| ≤ 2e-6; NaN and ±Infinity exactly where the JS has them; within NEAR of θc
 * compared by angle (the GPU value is the JS value at an angle within 1e-5 rad). Cases GLSL
 * leaves undefined are collected in `undefinedSeen` instead; the index pairs with a row held to
 * 2e-6 between NEAR and 2.5 NEAR below θc, in `strictBelow`.
 */
function compare(methodId, rows, gpuValues, failures, undefinedSeen = [], strictBelow = new Set()) {
  const method = methodById(methodId);
  let worst = 0;
  rows.forEach((row, i) => {
    const [c, a, b, d] = row;
    const gpu = gpuValues[i];
    const js = method.evaluate('fp32', c, a, b, ...(method.kind === 'conductor' ? [d] : []));
    const where = `${methodId}(${row.join(', ')})`;
    if (undefinedInGlsl(methodId, row)) {
      undefinedSeen.push(`${where} = ${gpu} (JS models ${js})`);
      return;
    }
    if (!Number.isFinite(js) || !Number.isFinite(gpu)) {
      if (!Object.is(js, gpu)) failures.push(`${where}: gpu ${gpu}, js ${js}`);
      return;
    }
    const critical = method.kind === 'dielectric' ? criticalAngle(a, b) : null;
    const theta = Math.acos(Math.min(1, Math.max(-1, c)));
    if (critical !== null && c >= 0 && c <= 1 && Math.abs(theta - critical) < NEAR) {
      const near = [-1e-5, 0, 1e-5].map((dt) => method.evaluate('fp32', Math.cos(theta + dt), a, b));
      if (gpu < Math.min(...near) - 2e-6 || gpu > Math.max(...near) + 2e-6) {
        failures.push(`${where} near θc: gpu ${gpu} outside JS [${Math.min(...near)}, ${Math.max(...near)}]`);
      }
      return;
    }
    const error = Math.abs(gpu - js);
    worst = Math.max(worst, error);
    if (critical !== null && critical - theta >= NEAR && critical - theta < 2.5 * NEAR) strictBelow.add(`${a} → ${b}`);
    if (!(error <= 2e-6)) failures.push(`${where}: gpu ${gpu}, js ${js}, error ${error.toExponential(2)}`);
  });
  return worst;
}

test('every GLSL method in highp matches its JS float32 twin; NaN where the JS gives NaN', async ({ page }) => {
  await openLab(page, './embed.html?panel=stability');
  const dielectric = dielectricRows();
  const conductor = conductorRows();
  const jobs = METHOD_IDS.map((methodId) => ({
    methodId, precision: 'highp', rows: methodById(methodId).kind === 'dielectric' ? dielectric : conductor,
  }));
  const results = await gpuEvaluate(page, jobs);
  const failures = [];
  const worst = {};
  const undefinedSeen = [];
  const strictBelow = new Set();
  jobs.forEach((job, k) => { worst[job.methodId] = compare(job.methodId, job.rows, results[k], failures, undefinedSeen, strictBelow); });
  console.log(`[gpu methods] worst |gpu - js fp32|: ${JSON.stringify(Object.fromEntries(Object.entries(worst).map(([m, e]) => [m, e.toExponential(1)])))}`);
  console.log(`[gpu methods] undefined in GLSL, this GPU gives e.g. ${undefinedSeen.slice(0, 3).join('; ')}`);
  expect(failures.slice(0, 20)).toEqual([]);
  const withCritical = PAIRS.filter(([nI, nT]) => nI > nT).map((pair) => pair.map(f).join(' → '));
  expect([...strictBelow].sort(), 'every pair with a critical angle has rows just outside NEAR held to 2e-6').toEqual(withCritical.sort());
  // NaN and Infinity survive the read-back: a NaN cosine gives NaN, an infinite one -Infinity.
  const at = (id, pick) => results[METHOD_INDEX[id]][dielectric.findIndex(pick)];
  expect(at('exact-cg', ([c]) => Number.isNaN(c))).toBeNaN();
  expect(at('schlick-mul', ([c]) => c === Infinity)).toBe(-Infinity);
  // The literal order gives R = 1 for matched media at grazing (cos 1e-4), the safe order 0.
  const matched = dielectric.findIndex(([c, nI, nT]) => nI === 1 && nT === 1 && c === f(1e-4));
  expect(results[METHOD_INDEX['exact-cg-literal']][matched]).toBe(1);
  expect(results[METHOD_INDEX['exact-cg']][matched]).toBe(0);
});

test('mediump: the same source under mediump; at full precision it matches float32', async ({ page }) => {
  await openLab(page, './embed.html?panel=stability');
  const rows = dielectricRows().filter(([c]) => c >= 0 && c <= 1);
  const probe = await page.evaluate(() => window.fresnelLab.panels.stability.precisionProbe);
  expect(probe.highpBits).toBe(24);
  expect(probe.mediumpBits).toBeGreaterThanOrEqual(11); // GLSL ES 3.00 §4.5.2: mediump is at least float16
  expect(probe.mediumpBits).toBeLessThanOrEqual(24);
  expect(probe.mediumpIsFullPrecision).toBe(probe.mediumpBits === 24);
  const ids = ['exact-cg', 'exact-cg-literal', 'schlick-mul'];
  const results = await gpuEvaluate(page, ids.map((methodId) => ({ methodId, precision: 'mediump', rows })));
  const failures = [];
  if (probe.mediumpIsFullPrecision) {
    ids.forEach((methodId, k) => compare(methodId, rows, results[k], failures));
  } else {
    // True half precision: every value is still a number, and Schlick stays within 0.01 (the float16
    // emulation of methods.js gives 1.9e-3 for air to 1.5).
    results[2].forEach((v, i) => {
      const js = methodById('schlick-mul').evaluate('fp16', ...rows[i].slice(0, 3));
      if (!(Math.abs(v - js) < 0.01)) failures.push(`schlick-mul mediump (${rows[i]}): gpu ${v}, js fp16 ${js}`);
    });
  }
  expect(failures.slice(0, 20)).toEqual([]);
});
