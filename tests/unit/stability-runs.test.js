import { afterEach, describe, expect, it, vi } from 'vitest';
import { createStabilityRuns, pairFor } from '../../src/panels/stability/runs.js';
import {
  describeText, gpuMessage, mapLabel, mapsCsv, noteText, pngCaption, readBackWords, readoutText, sideTitle,
} from '../../src/panels/stability/words.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';

const WIDTH = 181; // θ = 0°, 0.5°, …, 90°
const HEIGHT = 106; // n_i/n_t = 0.40, 0.42, …, 2.50
const CELLS = WIDTH * HEIGHT;

/**
 * Unpolarized R from n_i = m into n_t = 1, from the s and p Fresnel equations (Hecht, Optics, §4.6),
 * written here apart from src/optics: Snell's law for cos θt, R = 1 under total internal
 * reflection, R = 0 for matched media.
 */
function fresnelSP(cosI, m) {
  if (m === 1) return 0;
  const sinT2 = m * m * (1 - cosI * cosI);
  if (sinT2 >= 1) return 1;
  const cosT = Math.sqrt(1 - sinT2);
  const rs = (m * cosI - cosT) / (m * cosI + cosT);
  const rp = (m * cosT - cosI) / (m * cosT + cosI);
  return (rs * rs + rp * rp) / 2;
}

/** Cell k of the map (row-major, k = j·WIDTH + i): cos θ and the index ratio, from the grid's own definition. */
const cellOf = (k) => {
  const i = k % WIDTH;
  const j = Math.floor(k / WIDTH);
  return { cos: i === WIDTH - 1 ? 0 : Math.cos((i / 2) * (Math.PI / 180)), ratio: (20 + j) / 50 };
};

/**
 * A GPU whose answers are known by construction, whatever the method: the first 100 cells NaN,
 * the next 200 at 1.5 (outside [0, 1]), the next 300 off the exact R by 0.02 (towards the middle,
 * so inside [0, 1]), every other cell the exact R (rounded to float32, a few 1e-8 off).
 */
const KNOWN = { notFinite: 100, outOfRange: 200, off: 300 };
function knownValue(k) {
  if (k < KNOWN.notFinite) return NaN;
  if (k < KNOWN.notFinite + KNOWN.outOfRange) return 1.5;
  const { cos, ratio } = cellOf(k);
  const r = fresnelSP(cos, ratio);
  if (k < KNOWN.notFinite + KNOWN.outOfRange + KNOWN.off) return r > 0.5 ? r - 0.02 : r + 0.02;
  return r;
}
const knownGpu = (options = {}) => fakeGpu({
  evaluate: ({ inputs }) => Float32Array.from({ length: inputs.length / 4 }, (_, k) => knownValue(k)),
  ...options,
});
/** The counts of the known GPU's map: at a tolerance under 0.02 the shifted cells fail, above it they pass. */
const KNOWN_COUNTS = { fine: CELLS - 600, aboveTolerance: 300, outOfRange: 200, notFinite: 100 };
const KNOWN_COUNTS_LOOSE = { fine: CELLS - 300, aboveTolerance: 0, outOfRange: 200, notFinite: 100 };

/** Runs on a stand-in GPU, with their values object and read-back counter. */
function setup(values = {}, fake = knownGpu()) {
  const state = { method: 'exact-cg', precision: 'mediump', tolerance: 0.001, ...values };
  const onRead = vi.fn();
  const gpu = createReadBackGpu({ words: readBackWords, ...fake.options() });
  const runs = createStabilityRuns({ values: state, gpu, onRead });
  runs.update();
  return { runs, state, fake, onRead, gpu };
}
const evaluations = (fake) => fake.evaluators.reduce((n, e) => n + e.evaluate.mock.calls.length, 0);

// What the panel says of each GPU problem, as a user reads it (createReadBackGpu's words).
const LOST = 'The graphics context was lost; the GPU map comes back when it is restored.';
const NO_FLOAT = 'This GPU cannot render to float32 textures (no EXT_color_buffer_float). '
  + 'The GPU map needs WebGL2 with float render targets; the JavaScript map still works.';

afterEach(() => vi.restoreAllMocks());

describe('the stability runs', () => {
  it('pairs each precision with a GPU qualifier and a JavaScript context', () => {
    expect(pairFor('highp')).toEqual({ gpu: 'highp', js: 'fp32', selected: 'gpu' });
    expect(pairFor('mediump')).toEqual({ gpu: 'mediump', js: 'fp16', selected: 'gpu' });
    expect(pairFor('fp16')).toEqual({ gpu: 'mediump', js: 'fp16', selected: 'js' });
    expect(pairFor('fp64')).toEqual({ gpu: 'highp', js: 'fp64', selected: 'js' });
  });

  it('classifies the values read back; reads them once per method and qualifier, not per tolerance', () => {
    const { runs, state, fake, onRead } = setup({ method: 'schlick-mul', precision: 'highp', tolerance: 0.05 });
    expect(onRead).toHaveBeenCalledTimes(2); // the precision probe, then the map
    expect(runs.maps.gpu.counts).toEqual(KNOWN_COUNTS_LOOSE);
    expect([...runs.maps.gpu.values.subarray(0, 3)]).toEqual([NaN, NaN, NaN]); // the values read back, kept with the map
    state.tolerance = 0.001;
    runs.update();
    expect(runs.maps.gpu.counts).toEqual(KNOWN_COUNTS);
    state.precision = 'fp32'; // the same GPU qualifier: nothing read again
    runs.update();
    expect(evaluations(fake)).toBe(1);
    state.method = 'schlick-tir';
    runs.update();
    expect(evaluations(fake)).toBe(2);
    expect(fake.evaluators[0].evaluate.mock.calls[1][0]).toMatchObject({ methodId: 'schlick-tir', precision: 'highp' });
    state.method = 'schlick-mul';
    runs.update();
    expect(evaluations(fake)).toBe(2);
    expect(onRead).toHaveBeenCalledTimes(3);
  });

  it('says what mediump is here, measured, beside what the driver claims', () => {
    const full = setup();
    expect(noteText(full.runs)).toBe('mediump runs at full precision on this GPU: 1 + 2⁻¹² ≠ 1, 24 significand bits '
      + '(the driver claims 11 bits; not trusted, measured instead). Its map matches highp; '
      + 'the JavaScript float16 map shows what a phone GPU with true half precision does, with every operation exactly rounded '
      + "(a GPU's own half precision errs a little more: 1.3–1.6 times on an NVIDIA H200).");
    expect(full.runs.fullMediump).toBe(true);
    expect(describeText(full.state, full.runs)).toMatch(/ mediump runs at full precision on this GPU\.$/);
    expect(pngCaption(full.state, full.runs)).toBe('Exact c/g (safe order) (mediump runs at full precision on this GPU)');
    const half = setup({}, knownGpu({ probe: HALF_PRECISION }));
    expect(noteText(half.runs)).toBe('mediump runs at reduced precision on this GPU: 11 significand bits (float16 has 11) '
      + '(the driver claims 11 bits; not trusted, measured instead).');
    expect(half.runs.fullMediump).toBe(false);
  });

  it('describes both maps with their counts, names them, and lists the counts for the CSV', () => {
    const { runs, state } = setup({ method: 'exact-sp', precision: 'fp64' });
    // The GPU map's counts are the known GPU's; float64 s/p agrees with the c/g reference everywhere.
    expect(describeText(state, runs)).toBe('Exact s/p (Snell) over 181 angles × 106 index ratios: '
      + 'on this GPU in highp: 18586 fine, 300 with error above 0.00100, 200 outside [0, 1] and 100 NaN or infinite; '
      + 'in JavaScript float64: 19186 fine, 0 with error above 0.00100, 0 outside [0, 1] and 0 NaN or infinite.');
    expect(sideTitle(runs.pair, 'js')).toBe('JavaScript · fp64');
    expect(sideTitle(runs.pair, 'gpu')).toBe('On this GPU · highp');
    expect(mapLabel(state, runs, 'js')).toBe('Stability map of Exact s/p (Snell), JavaScript · fp64: 0 of 19186 cells fail. '
      + 'Arrow keys move the probe.');
    expect(mapLabel(state, runs, 'gpu')).toBe('Stability map of Exact s/p (Snell), On this GPU · highp: 600 of 19186 cells fail. '
      + 'Arrow keys move the probe.');
    expect(mapsCsv(state, runs)).toEqual({
      filename: 'stability-exact-sp-fp64.csv',
      columns: { class: ['fine', 'aboveTolerance', 'outOfRange', 'notFinite'], gpu_highp: [18586, 300, 200, 100], js_fp64: [19186, 0, 0, 0] },
    });
    state.tolerance = 0.5;
    runs.update();
    expect(describeText(state, runs)).toBe('Exact s/p (Snell) over 181 angles × 106 index ratios: '
      + 'on this GPU in highp: 18886 fine, 0 with error above 0.500, 200 outside [0, 1] and 100 NaN or infinite; '
      + 'in JavaScript float64: 19186 fine, 0 with error above 0.500, 0 outside [0, 1] and 0 NaN or infinite.');
  });

  it('moves the probe by keys from the middle, 10 cells with Shift, within the map, and reads it out', () => {
    const { runs } = setup({ method: 'schlick-mul', precision: 'fp32' });
    expect(runs.probed).toBeNull();
    expect(readoutText(runs)).toBe('');
    expect(runs.moveProbe('a')).toBe(false);
    expect(runs.moveProbe('toString')).toBe(false); // not an own key of the moves
    expect(runs.probeCell).toBeNull();
    expect(runs.moveProbe('ArrowRight')).toBe(true);
    expect(runs.probeCell).toEqual({ i: 91, j: 53 });
    runs.moveProbe('ArrowUp', true);
    expect(runs.probeCell).toEqual({ i: 91, j: 63 });
    runs.moveProbe('End');
    expect(runs.probeCell).toEqual({ i: 180, j: 63 });
    runs.moveProbe('ArrowDown', true);
    runs.moveProbe('Home');
    expect(runs.probeCell).toEqual({ i: 0, j: 53 });
    // θ = 60°, n_i/n_t = 0.5: exact R (Hecht) 0.0896…; Schlick with R0 = ((1 − 0.5)/(1 + 0.5))² = 1/9 is
    // 1/9 + (8/9)(1 − cos 60°)⁵ = 1/9 + 1/36 = 5/36 = 0.138889, 0.049 too high.
    runs.setProbe({ i: 120, j: 5 });
    const exact = fresnelSP(cellOf(5 * WIDTH + 120).cos, 0.5);
    expect(runs.probed).toEqual({
      thetaDeg: expect.closeTo(60, 12), ratio: expect.closeTo(0.5, 12), critical: null, reference: expect.closeTo(exact, 12),
      gpu: { value: Math.fround(exact), class: 'fine' }, // the known GPU's value at that cell
      js: { value: expect.closeTo(5 / 36, 6), class: 'aboveTolerance' },
    });
    expect(readoutText(runs)).toBe(`θ = 60.00°, n_i/n_t = 0.500 · exact R = ${exact.toPrecision(6)} · `
      + `GPU highp: ${Math.fround(exact).toPrecision(6)} (fine) · JS float32 (highp): 0.138889 (error above tolerance)`);
    runs.setProbe({ i: 0, j: 0 }); // the first cell: NaN on the known GPU
    expect(runs.probed.gpu).toEqual({ value: NaN, class: 'notFinite' });
    expect(readoutText(runs)).toContain(' · GPU highp: NaN (NaN or infinite) · ');
    runs.setProbe({ i: 120, j: 100 }); // n_i/n_t = 2.4: past θc = asin(1/2.4) = 24.62°
    expect(readoutText(runs)).toMatch(/^θ = 60\.00°, n_i\/n_t = 2\.400 \(θc = 24\.62°\) · exact R = 1\.00000 · /);
  });

  it('keeps the maps already read back through a loss; one not read yet waits for the restore, then is read', () => {
    const { runs, state, fake, onRead } = setup({ method: 'schlick-mul', precision: 'highp' });
    fake.lose();
    runs.update();
    expect(runs.maps.gpu.counts).toEqual(KNOWN_COUNTS); // read before the loss: still true
    Object.assign(state, { method: 'exact-cg', precision: 'fp64' }); // GPU highp, not read yet; JS float64, the reference itself
    runs.update();
    expect(runs.maps.gpu).toBeNull();
    expect(gpuMessage(runs)).toBe(LOST);
    expect(noteText(runs)).toBe(LOST);
    // The description names the loss, not another cause.
    expect(describeText(state, runs)).toBe('Exact c/g (safe order) over 181 angles × 106 index ratios: no GPU map; '
      + 'in JavaScript float64: 19186 fine, 0 with error above 0.00100, 0 outside [0, 1] and 0 NaN or infinite. '
      + `${LOST}`);
    expect(onRead).toHaveBeenCalledTimes(2);
    fake.restore();
    runs.update();
    expect(runs.maps.gpu.counts).toEqual(KNOWN_COUNTS);
    expect(fake.evaluators[1].evaluate).toHaveBeenCalledOnce(); // on the new evaluator
    expect(gpuMessage(runs)).toBe('');
  });

  it('drops what a read that lost the context returned: no map, the loss said, read again after the restore', () => {
    const { runs, state, fake, onRead } = setup({ method: 'exact-cg', precision: 'highp' });
    fake.loseDuringNextRead();
    state.method = 'exact-sp';
    runs.update();
    expect(runs.maps.gpu).toBeNull();
    expect(gpuMessage(runs)).toBe(LOST);
    expect(describeText(state, runs)).toMatch(new RegExp(`: no GPU map; in JavaScript float32 \\(highp\\): .*\\. ${LOST}$`));
    expect(onRead).toHaveBeenCalledTimes(2); // the probe and the first map: nothing for the lost read
    fake.lose();
    fake.restore();
    runs.update();
    expect(runs.maps.gpu.counts).toEqual(KNOWN_COUNTS); // read again: the zeros of the lost read were not kept
    expect(fake.evaluators[1].evaluate).toHaveBeenCalledOnce();
  });

  it('says a failed evaluation, a GPU without float targets and a refused shader, each as itself', () => {
    const failing = setup({ precision: 'highp' }, fakeGpu({ evaluate: () => { throw new RangeError('19186 samples do not fit one texture'); } }));
    expect(failing.runs.maps.gpu).toBeNull();
    expect(failing.runs.maps.js).not.toBeNull();
    expect(gpuMessage(failing.runs)).toBe('The GPU evaluation failed: 19186 samples do not fit one texture');
    expect(describeText(failing.state, failing.runs)).toMatch(/: no GPU map; .*\. The GPU evaluation failed: 19186 samples do not fit one texture$/);
    const noFloatError = new GpuFloatUnavailable('This GPU cannot render to float32 textures (no EXT_color_buffer_float).');
    const noFloat = setup({ precision: 'fp64' }, fakeGpu({ evaluatorError: noFloatError }));
    expect(noFloat.onRead).not.toHaveBeenCalled();
    expect(gpuMessage(noFloat.runs)).toBe(NO_FLOAT);
    expect(noteText(noFloat.runs)).toBe(NO_FLOAT);
    expect(describeText(noFloat.state, noFloat.runs)).toBe('Exact c/g (safe order) over 181 angles × 106 index ratios: no GPU map; '
      + 'in JavaScript float64: 19186 fine, 0 with error above 0.00100, 0 outside [0, 1] and 0 NaN or infinite. '
      + `${NO_FLOAT}`);
    expect(mapsCsv(noFloat.state, noFloat.runs).columns).not.toHaveProperty('gpu_highp');
    vi.spyOn(console, 'error').mockImplementation(() => {});
    const log = "ERROR: 0:9: 'fm_evaluate' : no matching overloaded function found\n";
    const refused = setup({}, fakeGpu({ probeError: new ShaderError({ stage: 'fragment', log }) }));
    const refusal = 'This GPU could not compile the evaluation shader, so there is no GPU map: '
      + "ERROR: 0:9: 'fm_evaluate' : no matching overloaded function found. The JavaScript map still works.";
    expect(gpuMessage(refused.runs)).toBe(refusal);
    expect(describeText(refused.state, refused.runs)).toMatch(new RegExp(`: no GPU map; .*\\. ${refusal.replace(/[.()]/g, '\\$&')}$`));
    expect(describeText(refused.state, refused.runs)).not.toContain('float render targets');
  });

  it('says a restore that fails, and dispose frees the GPU and the maps', () => {
    const { runs, state, fake } = setup({ precision: 'highp' });
    fake.lose();
    fake.makeEvaluator.mockImplementationOnce(() => { throw new Error('out of memory'); });
    fake.restore();
    state.method = 'schlick-mul';
    runs.update();
    expect(gpuMessage(runs)).toBe('The GPU evaluator could not start again: out of memory');
    expect(describeText(state, runs)).toMatch(/: no GPU map; .*\. The GPU evaluator could not start again: out of memory$/);
    runs.dispose();
    expect(fake.context.dispose).toHaveBeenCalledOnce();
    expect(runs.maps).toEqual({ gpu: null, js: null });
    const fresh = setup();
    fresh.runs.dispose();
    expect(fresh.fake.evaluators[0].dispose).toHaveBeenCalledOnce();
    expect(fresh.fake.context.dispose).toHaveBeenCalledOnce();
  });
});
