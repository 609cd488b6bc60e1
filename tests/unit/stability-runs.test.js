import { afterEach, describe, expect, it, vi } from 'vitest';
import { createStabilityRuns, pairFor } from '../../src/panels/stability/runs.js';
import {
  describeText, gpuMessage, mapLabel, mapsCsv, noteText, pngCaption, readBackWords, readoutText, sideTitle,
} from '../../src/panels/stability/words.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { methodById } from '../../src/methods/methods.js';
import { fresnelExact } from '../../src/optics/fresnel.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';

const CELLS = 181 * 106;

/** A GPU that computes as the JavaScript float32 twin does (a highp GPU, or a mediump one at full precision). */
const float32Gpu = (options = {}) => fakeGpu({
  evaluate: ({ methodId, inputs }) => Float32Array.from({ length: inputs.length / 4 },
    (_, i) => methodById(methodId).evaluate('fp32', inputs[i * 4], inputs[i * 4 + 1], inputs[i * 4 + 2])),
  ...options,
});

/** A runs on a stand-in GPU, with its values object and read-back counter. */
function setup(values = {}, fake = float32Gpu()) {
  const state = { method: 'exact-cg', precision: 'mediump', tolerance: 0.001, ...values };
  const onRead = vi.fn();
  const gpu = createReadBackGpu({ words: readBackWords, ...fake.options() });
  const runs = createStabilityRuns({ values: state, gpu, onRead });
  runs.update();
  return { runs, state, fake, onRead, gpu };
}
const evaluations = (fake) => fake.evaluators.reduce((n, e) => n + e.evaluate.mock.calls.length, 0);
const total = (map) => Object.values(map.counts).reduce((a, b) => a + b, 0);

afterEach(() => vi.restoreAllMocks());

describe('the stability runs', () => {
  it('pairs each precision with a GPU qualifier and a JavaScript context', () => {
    expect(pairFor('highp')).toEqual({ gpu: 'highp', js: 'fp32', selected: 'gpu' });
    expect(pairFor('mediump')).toEqual({ gpu: 'mediump', js: 'fp16', selected: 'gpu' });
    expect(pairFor('fp16')).toEqual({ gpu: 'mediump', js: 'fp16', selected: 'js' });
    expect(pairFor('fp64')).toEqual({ gpu: 'highp', js: 'fp64', selected: 'js' });
  });

  it('classifies both maps; the GPU map is read back once per method and qualifier, not per tolerance', () => {
    const { runs, state, fake, onRead } = setup({ method: 'schlick-mul', precision: 'highp', tolerance: 0.05 });
    expect(onRead).toHaveBeenCalledTimes(2); // the precision probe, then the map
    expect(total(runs.maps.gpu)).toBe(CELLS);
    expect(runs.maps.gpu.counts).toEqual(runs.maps.js.counts); // the stand-in computes as float32 does
    const loose = runs.maps.gpu.counts.aboveTolerance;
    state.tolerance = 0.001;
    runs.update();
    expect(runs.maps.gpu.counts.aboveTolerance).toBeGreaterThan(loose);
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
    const half = setup({}, float32Gpu({ probe: HALF_PRECISION }));
    expect(noteText(half.runs)).toBe('mediump runs at reduced precision on this GPU: 11 significand bits (float16 has 11) '
      + '(the driver claims 11 bits; not trusted, measured instead).');
    expect(half.runs.fullMediump).toBe(false);
  });

  it('describes both maps, names them, and lists their counts for the CSV', () => {
    const { runs, state } = setup({ method: 'exact-sp', precision: 'fp64' });
    expect(describeText(state, runs)).toBe('Exact s/p (Snell) over 181 angles × 106 index ratios: '
      + `on this GPU in highp: ${runs.maps.gpu.counts.fine} fine, `
      + `${runs.maps.gpu.counts.aboveTolerance} with error above 0.00100, 0 outside [0, 1] and 0 NaN or infinite; in JavaScript float64: `
      + `${CELLS} fine, 0 with error above 0.00100, 0 outside [0, 1] and 0 NaN or infinite.`);
    expect(sideTitle(runs.pair, 'js')).toBe('JavaScript · fp64');
    expect(sideTitle(runs.pair, 'gpu')).toBe('On this GPU · highp');
    expect(mapLabel(state, runs, 'js'))
      .toBe(`Stability map of Exact s/p (Snell), JavaScript · fp64: 0 of ${CELLS} cells fail. Arrow keys move the probe.`);
    expect(mapsCsv(state, runs)).toEqual({
      filename: 'stability-exact-sp-fp64.csv',
      columns: { class: ['fine', 'aboveTolerance', 'outOfRange', 'notFinite'], gpu_highp: expect.any(Array), js_fp64: [CELLS, 0, 0, 0] },
    });
    state.tolerance = 0.5;
    expect(describeText(state, runs)).toContain('error above 0.500');
  });

  it('moves the probe by keys from the middle, 10 cells with Shift, within the map, and reads it out', () => {
    const { runs } = setup({ method: 'schlick-mul', precision: 'fp32' });
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
    runs.setProbe({ i: 120, j: 5 });
    const exact = fresnelExact(Math.cos((60 * Math.PI) / 180), 0.5, 1);
    const value = runs.maps.gpu.values[5 * 181 + 120];
    const jsValue = methodById('schlick-mul').evaluate('fp32', Math.cos(Math.PI / 3), 0.5, 1);
    expect(readoutText(runs)).toBe(`θ = 60.00°, n_i/n_t = 0.500 · exact R = ${exact.toPrecision(6)} · GPU highp: ${value.toPrecision(6)} `
      + `(error above tolerance) · JS float32 (highp): ${jsValue.toPrecision(6)} `
      + '(error above tolerance)');
    runs.setProbe({ i: 120, j: 100 }); // n_i/n_t = 2.4: past θc = 24.62°
    expect(readoutText(runs)).toMatch(/^θ = 60\.00°, n_i\/n_t = 2\.400 \(θc = 24\.62°\) · exact R = 1\.00000 · /);
  });

  it('keeps the maps already read back through a loss; one not read yet waits for the restore, then is read', () => {
    const { runs, state, fake, onRead } = setup({ method: 'schlick-mul', precision: 'highp' });
    fake.lose();
    runs.update();
    expect(runs.maps.gpu).not.toBeNull(); // read before the loss: still true
    state.method = 'schlick-tir';
    runs.update();
    expect(runs.maps.gpu).toBeNull();
    expect(gpuMessage(runs)).toBe(readBackWords.lost);
    expect(noteText(runs)).toBe(readBackWords.lost);
    expect(describeText(state, runs)).toContain('no GPU map');
    expect(onRead).toHaveBeenCalledTimes(2);
    fake.restore();
    runs.update();
    expect(runs.maps.gpu).not.toBeNull();
    expect(fake.evaluators[1].evaluate).toHaveBeenCalledOnce(); // on the new evaluator
    expect(gpuMessage(runs)).toBe('');
  });

  it('drops what a read that lost the context returned: no map, the loss said, read again after the restore', () => {
    const { runs, state, fake, onRead } = setup({ method: 'exact-cg', precision: 'highp' });
    fake.loseDuringNextRead();
    state.method = 'exact-sp';
    runs.update();
    expect(runs.maps.gpu).toBeNull();
    expect(gpuMessage(runs)).toBe(readBackWords.lost);
    expect(onRead).toHaveBeenCalledTimes(2); // the probe and the first map: nothing for the lost read
    fake.lose();
    fake.restore();
    runs.update();
    expect(runs.maps.gpu.counts).toEqual(runs.maps.js.counts); // read again: the zeros of the lost read were not kept
    expect(fake.evaluators[1].evaluate).toHaveBeenCalledOnce();
  });

  it('says a failed evaluation, and a GPU that cannot start, with the JavaScript map still there', () => {
    const failing = setup({}, fakeGpu({ evaluate: () => { throw new RangeError('19186 samples do not fit one texture'); } }));
    expect(failing.runs.maps.gpu).toBeNull();
    expect(failing.runs.maps.js).not.toBeNull();
    expect(gpuMessage(failing.runs)).toBe('The GPU evaluation failed: 19186 samples do not fit one texture');
    const noFloatError = new GpuFloatUnavailable('This GPU cannot render to float32 textures (no EXT_color_buffer_float).');
    const noFloat = setup({}, fakeGpu({ evaluatorError: noFloatError }));
    expect(noFloat.onRead).not.toHaveBeenCalled();
    expect(gpuMessage(noFloat.runs)).toBe('This GPU cannot render to float32 textures (no EXT_color_buffer_float). '
      + 'The GPU map needs WebGL2 with float render targets; the JavaScript map still works.');
    expect(noteText(noFloat.runs)).toBe(gpuMessage(noFloat.runs));
    expect(describeText(noFloat.state, noFloat.runs)).toContain('no GPU map (no float render targets); in JavaScript float16 (mediump): ');
    expect(mapsCsv(noFloat.state, noFloat.runs).columns).not.toHaveProperty('gpu_mediump');
    vi.spyOn(console, 'error').mockImplementation(() => {});
    const log = "ERROR: 0:9: 'fm_evaluate' : no matching overloaded function found\n";
    const refused = setup({}, fakeGpu({ probeError: new ShaderError({ stage: 'fragment', log }) }));
    expect(gpuMessage(refused.runs)).toBe('This GPU could not compile the evaluation shader, so there is no GPU map: '
      + "ERROR: 0:9: 'fm_evaluate' : no matching overloaded function found. The JavaScript map still works.");
  });

  it('says a restore that fails, and dispose frees the GPU and the maps', () => {
    const { runs, state, fake } = setup();
    fake.lose();
    fake.makeEvaluator.mockImplementationOnce(() => { throw new Error('out of memory'); });
    fake.restore();
    state.method = 'schlick-mul';
    runs.update();
    expect(gpuMessage(runs)).toBe('The GPU evaluator could not start again: out of memory');
    runs.dispose();
    expect(fake.context.dispose).toHaveBeenCalledOnce();
    expect(runs.maps).toEqual({ gpu: null, js: null });
    const fresh = setup();
    fresh.runs.dispose();
    expect(fresh.fake.evaluators[0].dispose).toHaveBeenCalledOnce();
    expect(fresh.fake.context.dispose).toHaveBeenCalledOnce();
  });
});
