import { afterEach, describe, expect, it, vi } from 'vitest';
import { createShaderLabRuns } from '../../src/panels/shader-lab/runs.js';
import {
  codeErrors, criteriaRows, describeText, gradeCsv, mapLabel, mapMessage, mapTitle, noteText, readBackWords,
  spheresLabel, spheresMessage, summaryText,
} from '../../src/panels/shader-lab/words.js';
import { exerciseById } from '../../src/panels/shader-lab/exercises.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { fresnelConductor, fresnelExact } from '../../src/optics/fresnel.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';

const ONES = 'float fresnel(float cosTheta, float nI, float nT) {\n  return 1.0;\n}';
const BROKEN = 'float fresnel(float cosTheta, float nI, float nT) {\n  float m = nI / nT;\n'
  + '  float g = sqrt(1.0 - m * m + c * c);\n  return g;\n}';
const LOOP = 'float fresnel(float c, float a, float b) {\n  while (true) {}\n  return 0.0;\n}';
const BROKEN_LOG = "ERROR: 0:3: 'c' : undeclared identifier\nERROR: 0:3: '=' : cannot convert\n";
const clamp01 = (x) => Math.min(1, Math.max(0, x));

/**
 * A GPU that runs the student's code as its JavaScript twin would: the reference answers as the
 * float64 core rounded to float32, ONES as 1 everywhere; BROKEN is refused as ANGLE refuses it.
 */
const labGpu = (options = {}) => fakeGpu({
  evaluateSource: ({ key, source, inputs, extra, channels }) => {
    const text = key.split('|').slice(3).join('|');
    if (text === BROKEN) throw new ShaderError({ stage: 'fragment', log: BROKEN_LOG, source });
    const count = inputs.length / 4;
    const out = new Float32Array(count * channels);
    for (let i = 0; i < count; i += 1) {
      const c = clamp01(inputs[i * 4]);
      for (let ch = 0; ch < channels; ch += 1) {
        out[i * channels + ch] = text === ONES ? 1 : channels === 3
          ? fresnelConductor(c, inputs[i * 4 + 1 + ch], extra[i * 4 + ch])
          : fresnelExact(c, inputs[i * 4 + 1], inputs[i * 4 + 2]);
      }
    }
    return out;
  },
  ...options,
});

/** The lab's runs on a stand-in GPU with a stand-in sphere painter. */
function setup(values = {}, fake = labGpu()) {
  const state = { exercise: 'exact', code: '', precision: 'highp', homework: false, ...values };
  const painter = { paint: vi.fn(), dispose: vi.fn() };
  const onRead = vi.fn();
  const gpu = createReadBackGpu({ words: readBackWords, prepare: () => painter, ...fake.options() });
  const runs = createShaderLabRuns({ values: state, gpu, onRead });
  return { runs, state, fake, painter, onRead, gpu };
}
const sourceCalls = (fake, role) => fake.evaluators.flatMap((e) => e.evaluateSource.mock.calls).filter(([o]) => o.key.startsWith(role));

afterEach(() => vi.restoreAllMocks());

describe('the shader lab runs', () => {
  it('grades a reference answer: every criterion passes, the error is summed up, both maps are made', () => {
    const { runs, state, fake, onRead } = setup();
    state.code = exerciseById('exact').reference;
    runs.update();
    expect(runs.state.results.map((r) => r.pass)).toEqual([true, true]);
    expect(criteriaRows(runs).map((r) => [r.id, r.result.pass])).toEqual([['exactFromAir', true], ['matched', true]]);
    expect(runs.state.errors).toEqual([]);
    expect(summaryText(runs))
      .toMatch(/^2 of 2 criteria pass\. Against the exact R \(highp\): largest error \d\.\d\de(−\d+|\+0) at θ = .*; mean .*\.$/);
    expect(describeText(runs)).toMatch(/^Write the exact c\/g form: 2 of 2 criteria pass\. Largest error against the exact R in highp /);
    expect(runs.state.maps.student.counts.fine).toBe(91 * 54);
    expect(mapLabel(runs, 'reference')).toBe(`Stability map of a reference answer: 0 of ${91 * 54} cells fail`);
    expect(mapTitle(state, 'student')).toBe('Your function · highp');
    expect(mapMessage(runs, 'student')).toBe('');
    expect(onRead).toHaveBeenCalledOnce();
    // highp and mediump over the grading grid, then the map of each: four programs on the GPU.
    expect(sourceCalls(fake, 'student|').map(([o]) => o.key.split('|')[2])).toEqual(['highp', 'mediump', 'highp']);
    expect(sourceCalls(fake, 'reference|')).toHaveLength(1);
  });

  it('keeps the reference map, and only the newest code\'s programs', () => {
    const { runs, state, fake } = setup();
    runs.update();
    state.code = ONES;
    runs.update();
    expect(sourceCalls(fake, 'reference|')).toHaveLength(1); // the reference answer does not change
    expect(fake.evaluators[0].forget).toHaveBeenCalledTimes(2); // the start code, then ONES
    runs.update();
    expect(fake.evaluators[0].forget).toHaveBeenCalledTimes(2); // the same code: its programs stay
    state.precision = 'mediump';
    runs.update();
    expect(sourceCalls(fake, 'reference|')).toHaveLength(2);
    expect(mapTitle(state, 'reference')).toBe('A reference answer · mediump');
  });

  it('names what fails and why: R = 1 everywhere passes only total internal reflection', () => {
    const { runs, state } = setup({ exercise: 'tir', code: ONES });
    runs.update();
    expect(runs.state.results.map((r) => r.pass)).toEqual([false, true, false, true]);
    // From air, R = 1 is right only at θ = 90° (once for each of the three index pairs), and farthest
    // from the exact R where that is smallest: head-on into water, R0 = (0.33 / 2.33)².
    const [fromAir] = runs.state.results;
    expect(fromAir).toMatchObject({ id: 'exactFromAir', code: 'aboveTolerance', target: 'exact', tolerance: 1e-5, failed: fromAir.checked - 3 });
    expect(fromAir.worst).toMatchObject({ kind: 'aboveTolerance', value: 1, channel: null, case: { thetaDeg: 0, nI: 1, nT: Math.fround(1.33) } });
    expect(fromAir.worst.reference).toBeCloseTo((0.33 / 2.33) ** 2, 6);
    expect(fromAir.worst.error).toBeCloseTo(1 - (0.33 / 2.33) ** 2, 6);
    expect(describeText(runs)).toContain('2 of 4 criteria pass (failing: The exact R from air at every angle, grazing included; ');
    state.exercise = 'gold';
    state.code = '';
    runs.update();
    expect(runs.state.maps).toEqual({ student: null, reference: null }); // a conductor has no (θ, n_i/n_t) map
    expect(spheresLabel(runs)).toMatch(/^Two gold spheres/);
  });

  it('shows the driver\'s refusal at the student\'s own lines; a loop is refused before the GPU sees it', () => {
    const { runs, state, fake, onRead } = setup({ code: BROKEN });
    runs.update();
    expect(runs.state.errors).toEqual([
      { line: 3, code: 'driver', text: "'c' : undeclared identifier" }, { line: 3, code: 'driver', text: "'=' : cannot convert" },
    ]);
    expect(runs.state.results).toEqual([]);
    expect(summaryText(runs)).toBe('Not graded: see what stopped it above.');
    expect(describeText(runs)).toBe("Write the exact c/g form: not graded; line 3: 'c' : undeclared identifier line 3: '=' : cannot convert");
    expect(spheresMessage(runs)).toBe('No spheres until the code compiles and runs.');
    expect(mapMessage(runs, 'student')).toBe('No map until the code compiles and runs.');
    expect(onRead).toHaveBeenCalledOnce(); // it reached the GPU
    state.code = LOOP;
    const before = sourceCalls(fake, '').length;
    runs.update();
    expect(runs.state.errors).toEqual([{ line: 2, code: 'loop' }]);
    expect(sourceCalls(fake, '').length).toBe(before);
    expect(onRead).toHaveBeenCalledOnce();
  });

  it('stops a grading that finds the context lost: nothing of it shown, the loss said, the code held back after the restore', () => {
    const { runs, state, fake, onRead } = setup({ code: ONES });
    fake.loseDuringNextRead();
    runs.update();
    expect(runs.state.values).toEqual({});
    expect(runs.state.results).toEqual([]);
    expect(summaryText(runs)).toBe(readBackWords.lost);
    expect(describeText(runs)).toBe(`Write the exact c/g form: ${readBackWords.lost}`);
    expect(spheresMessage(runs)).toBe(readBackWords.lost);
    expect(mapMessage(runs, 'student')).toBe(readBackWords.lost);
    expect(gradeCsv(runs).columns.yours_highp.every((v) => v === '')).toBe(true);
    expect(onRead).toHaveBeenCalledOnce();
    fake.lose();
    runs.update(); // while lost: nothing is read
    expect(sourceCalls(fake, '')).toHaveLength(1);
    fake.restore();
    runs.update();
    const stall = /^The graphics card stopped responding while this code was graded/;
    expect(runs.state.stalled).toBe(true);
    expect(codeErrors(runs)).toEqual([{ line: null, message: expect.stringMatching(stall) }]);
    expect(summaryText(runs)).toBe('Not graded: see what stopped it above.');
    expect(fake.evaluators[1].evaluateSource).not.toHaveBeenCalled(); // it may be what stopped the GPU
    state.code = exerciseById('exact').reference; // other code is graded
    runs.update();
    expect(runs.state.results.every((r) => r.pass)).toBe(true);
    state.code = ONES;
    runs.retry(); // asked for by the student: once more
    runs.update();
    expect(runs.state.results).toHaveLength(2);
  });

  it('drops a grading that a newer one replaced while it ran, and keeps the newer one\'s', () => {
    let runs = null;
    let nested = false;
    const fake = labGpu();
    const ones = fake.makeEvaluator;
    fake.makeEvaluator = vi.fn((gl) => {
      const evaluator = ones(gl);
      const evaluate = evaluator.evaluateSource.getMockImplementation();
      evaluator.evaluateSource.mockImplementation((options) => {
        if (!nested && options.key.endsWith(`|${ONES}`)) { // a change arrives while ONES is graded
          nested = true;
          state.code = exerciseById('exact').reference;
          runs.update();
        }
        return evaluate(options);
      });
      return evaluator;
    });
    const set = setup({ code: ONES }, fake);
    ({ runs } = set);
    const { state } = set;
    runs.update();
    expect(nested).toBe(true);
    expect(runs.state.results.map((r) => r.pass)).toEqual([true, true]); // the newer code's grade, not ONES's
    // ONES's grading stopped at the read during which it went stale: no mediump, no map for it.
    expect(sourceCalls(fake, 'student|').filter(([o]) => o.key.endsWith(`|${ONES}`))).toHaveLength(1);
  });

  it('paints the spheres with the graded code, and says when they cannot be drawn beside the page\'s code', () => {
    const { runs, painter, state } = setup({ code: exerciseById('exact').reference });
    const target = /** @type {any} */ ({});
    expect(runs.paint(target)).toBeNull(); // not graded yet
    expect(painter.paint).not.toHaveBeenCalled();
    runs.update();
    expect(runs.paint(target)).toBeNull();
    expect(spheresMessage(runs)).toBe('');
    expect(painter.paint).toHaveBeenCalledWith(target, state.code, exerciseById('exact'), null);
    const log = "ERROR: 0:10002: 'environment' : redefinition";
    const refusal = new ShaderError({ stage: 'fragment', log });
    painter.paint.mockImplementation(() => { throw refusal; });
    runs.update();
    expect(runs.paint(target)).toBe(refusal);
    expect(runs.state.spheres).toBe(refusal);
    expect(spheresMessage(runs)).toBe(`The spheres could not be drawn beside the page’s lighting code: ${log} `
      + '(is one of your names environment, skyLight, castStage or linearToSrgb?).');
  });

  it('says a GPU without float targets, or one that refuses the lab\'s own shaders, and grades nothing there', () => {
    const why = 'This GPU cannot render to float32 textures (no EXT_color_buffer_float).';
    const noFloat = setup({}, labGpu({ evaluatorError: new GpuFloatUnavailable(why) }));
    noFloat.runs.update();
    expect(summaryText(noFloat.runs)).toBe(`${why} Grading needs WebGL2 with float render targets.`);
    expect(describeText(noFloat.runs)).toBe(`Write the exact c/g form: ${summaryText(noFloat.runs)}`);
    vi.spyOn(console, 'error').mockImplementation(() => {});
    const log = "ERROR: 0:1: 'injected refusal' : this driver refuses the shader";
    const refused = setup({}, labGpu({ probeError: new ShaderError({ stage: 'fragment', log }) }));
    refused.runs.update();
    expect(summaryText(refused.runs)).toBe(`This GPU could not compile the lab’s own shaders, so nothing can be graded here: ${log}.`);
    expect(refused.runs.state.errors).toEqual([]); // not the student's error
    expect(refused.onRead).not.toHaveBeenCalled();
  });

  it('says where mediump cannot fail, only for an exercise with a mediump criterion', () => {
    const full = setup({ exercise: 'mediump' });
    expect(noteText(full.runs)).toBe('This GPU runs mediump at full float32 precision, so the mediump criteria cannot fail here; '
      + 'on a phone with half precision they can.');
    full.state.exercise = 'exact';
    expect(noteText(full.runs)).toBe('');
    expect(noteText(setup({ exercise: 'mediump' }, labGpu({ probe: HALF_PRECISION })).runs)).toBe('');
  });

  it('lists the cases and the values read back for the CSV, per channel for a conductor', () => {
    const { runs, state } = setup({ code: ONES });
    runs.update();
    const { columns, filename } = gradeCsv(runs);
    expect(filename).toBe('shader-lab-exact.csv');
    expect(Object.keys(columns)).toEqual(['case', 'cos', 'nI', 'nT', 'exact', 'yours_highp', 'yours_mediump']);
    expect(new Set(columns.yours_highp)).toEqual(new Set([1]));
    state.exercise = 'gold';
    state.code = exerciseById('gold').reference;
    runs.update();
    const gold = gradeCsv(runs).columns;
    expect(Object.keys(gold)).toContain('yours_mediump_blue');
    expect(gold.yours_highp_red[0]).toBeCloseTo(gold.exact_red[0], 6);
  });

  it('dispose stops every grading and frees the painter, the evaluator and the context', () => {
    const { runs, fake, painter, onRead } = setup({ code: ONES });
    runs.dispose();
    runs.update();
    expect(runs.state.results).toEqual([]);
    expect(onRead).not.toHaveBeenCalled();
    expect(painter.dispose).toHaveBeenCalledOnce();
    expect(fake.evaluators[0].dispose).toHaveBeenCalledOnce();
    expect(fake.context.dispose).toHaveBeenCalledOnce();
  });
});
