import { afterEach, describe, expect, it, vi } from 'vitest';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { isStaleRun } from '../../src/panels/shared/createRunGate.js';
import { WebGL2Unavailable } from '../../src/gl/webgl2Unavailable.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';

const WORDS = {
  unavailable: 'The map needs float targets; the rest still works.',
  refused: (line) => `Refused: ${line}.`,
  lost: 'Lost; back when restored.',
};
const inputs = new Float32Array(8);

afterEach(() => vi.restoreAllMocks());

describe('createReadBackGpu', () => {
  it('starts an evaluator on a context of its own and measures what mediump is', () => {
    const fake = fakeGpu({ probe: HALF_PRECISION });
    const prepare = vi.fn(() => ({ painter: true }));
    const gpu = createReadBackGpu({ words: WORDS, prepare, ...fake.options() });
    expect(gpu.ready).toBe(true);
    expect(gpu.problem).toBe('');
    expect(gpu.gl).toBe(fake.gl);
    expect(gpu.evaluator).toBe(fake.evaluators[0]);
    expect(gpu.precision.probe).toBe(HALF_PRECISION);
    expect(gpu.precision.claimed.mediump.precision).toBe(10);
    expect(prepare).toHaveBeenCalledWith(fake.evaluators[0], fake.gl);
    expect(gpu.prepared).toEqual({ painter: true });
  });

  it('says no WebGL2 and no float target in the browser\'s words, then the panel\'s', () => {
    const none = fakeGpu();
    none.makeContext.mockImplementation(() => { throw new WebGL2Unavailable('This browser has no WebGL2.'); });
    const a = createReadBackGpu({ words: WORDS, ...none.options() });
    expect([a.ready, a.gl, a.evaluator]).toEqual([false, null, null]);
    expect(a.problem).toBe('This browser has no WebGL2. The map needs float targets; the rest still works.');
    const noFloat = fakeGpu({ evaluatorError: new GpuFloatUnavailable('No float targets here.') });
    const b = createReadBackGpu({ words: WORDS, ...noFloat.options() });
    expect(b.problem).toBe('No float targets here. The map needs float targets; the rest still works.');
    expect(b.gl).toBe(noFloat.gl); // the context stays until dispose
    b.dispose();
    expect(noFloat.context.dispose).toHaveBeenCalledOnce();
  });

  it('words a refused shader of its own with the driver\'s first error line, and logs the whole error', () => {
    const log = vi.spyOn(console, 'error').mockImplementation(() => {});
    const driverLog = "WARNING: 0:2: unused\nERROR: 0:7: 'q' : undeclared identifier\n";
    const refusal = new ShaderError({ stage: 'fragment', log: driverLog, source: 'x' });
    const fake = fakeGpu({ probeError: refusal });
    const gpu = createReadBackGpu({ words: WORDS, ...fake.options() });
    expect(gpu.problem).toBe("Refused: ERROR: 0:7: 'q' : undeclared identifier.");
    expect(gpu.evaluator).toBeNull();
    expect(fake.evaluators[0].dispose).toHaveBeenCalledOnce();
    expect(log).toHaveBeenCalledWith(refusal);
    const silent = fakeGpu({ probeError: new ShaderError({ stage: 'link', log: '' }) });
    expect(createReadBackGpu({ words: WORDS, ...silent.options() }).problem).toBe('Refused: The shader program did not link:.');
  });

  it('lets an error that is no GPU problem through', () => {
    const fake = fakeGpu({ probeError: new TypeError('a bug') });
    expect(() => createReadBackGpu({ words: WORDS, ...fake.options() })).toThrow('a bug');
  });

  it('on a loss asks for the restore, stales the running run and says so; on the restore starts anew', () => {
    const fake = fakeGpu();
    const onChange = vi.fn();
    const prepare = vi.fn(() => 'painter');
    const gpu = createReadBackGpu({ words: WORDS, onChange, prepare, ...fake.options() });
    const run = gpu.gate().begin();
    const event = fake.lose();
    expect(event.defaultPrevented).toBe(true);
    expect(run.live).toBe(false);
    expect(isStaleRun(run.signal.reason)).toBe(true);
    expect([gpu.lost, gpu.ready, gpu.problem]).toEqual([true, false, WORDS.lost]);
    expect(onChange).toHaveBeenCalledOnce();
    expect(() => gpu.read(gpu.gate().begin(), (e) => e.evaluate({ inputs }))).toThrow(/Nothing can be read back now: Lost/);
    fake.restore();
    expect([gpu.lost, gpu.ready, gpu.problem]).toEqual([false, true, '']);
    expect(fake.makeEvaluator).toHaveBeenCalledTimes(2);
    expect(gpu.evaluator).toBe(fake.evaluators[1]);
    expect(prepare).toHaveBeenCalledTimes(2);
    expect(onChange).toHaveBeenCalledTimes(2);
  });

  it('takes a loss a step finds (before its event) as the event will: the run goes stale, its result is dropped', () => {
    const fake = fakeGpu({ evaluate: () => new Float32Array([0.5, 0.5]) });
    const gpu = createReadBackGpu({ words: WORDS, ...fake.options() });
    const gate = gpu.gate();
    expect(Array.from(gpu.read(gate.begin(), (e) => e.evaluate({ inputs })))).toEqual([0.5, 0.5]);
    fake.loseDuringNextRead();
    const run = gate.begin();
    let thrown = null;
    try {
      gpu.read(run, (e) => e.evaluate({ inputs }));
    } catch (error) {
      thrown = error;
    }
    expect(isStaleRun(thrown)).toBe(true);
    expect(thrown.message).toBe(WORDS.lost);
    expect(gpu.lost).toBe(true);
    // A step that throws because the context is gone is stale too, not the evaluator's error.
    const other = fakeGpu({ evaluate: () => { throw new Error('the WebGL context was lost'); } });
    const second = createReadBackGpu({ words: WORDS, ...other.options() });
    other.gl.isContextLost = () => true;
    const secondRun = second.gate().begin();
    expect(() => second.read(secondRun, () => { throw new Error('the WebGL context was lost'); })).toThrow(WORDS.lost);
  });

  it('passes a step\'s own error on, and stales a run a newer one replaced', () => {
    const gpu = createReadBackGpu({ words: WORDS, ...fakeGpu().options() });
    const gate = gpu.gate();
    const refusal = new ShaderError({ stage: 'fragment', log: 'ERROR: 0:1: no' });
    expect(() => gpu.read(gate.begin(), () => { throw refusal; })).toThrow(refusal);
    const old = gate.begin();
    gate.begin();
    expect(() => gpu.read(old, () => 1)).toThrow('A newer run began');
  });

  it('says a restore that fails in the panel\'s words, and never throws out of the event', () => {
    const fake = fakeGpu();
    const restartFailed = (error) => `Could not start again: ${error.message}`;
    const gpu = createReadBackGpu({ words: { ...WORDS, restartFailed }, ...fake.options() });
    fake.lose();
    fake.makeEvaluator.mockImplementationOnce(() => { throw new TypeError('out of memory'); });
    expect(() => fake.restore()).not.toThrow();
    expect([gpu.ready, gpu.problem]).toEqual([false, 'Could not start again: out of memory']);
    fake.lose();
    const unlike = new ShaderError({ stage: 'fragment', log: 'ERROR: 0:1: no' });
    vi.spyOn(console, 'error').mockImplementation(() => {});
    fake.evaluators[0].probePrecision.mockImplementationOnce(() => { throw unlike; });
    fake.makeEvaluator.mockImplementationOnce(() => fake.evaluators[0]);
    fake.restore();
    expect(gpu.problem).toMatch(/^Could not start again: The fragment shader did not compile:\nERROR: 0:1: no/);
    expect(fake.evaluators[0].dispose).toHaveBeenCalledOnce(); // the half-made evaluator is freed
    const plain = fakeGpu();
    const other = createReadBackGpu({ words: WORDS, ...plain.options() });
    plain.lose();
    plain.makeEvaluator.mockImplementationOnce(() => { throw new GpuFloatUnavailable('No float targets now.'); });
    plain.restore();
    expect(other.problem).toBe('No float targets now. The map needs float targets; the rest still works.');
  });

  it('dispose frees the panel\'s part, the evaluator and the context, and stales every run', () => {
    const fake = fakeGpu();
    const onChange = vi.fn();
    const part = { dispose: vi.fn() };
    const gpu = createReadBackGpu({ words: WORDS, onChange, prepare: () => part, ...fake.options() });
    const gate = gpu.gate();
    const run = gate.begin();
    gpu.dispose();
    gpu.dispose();
    expect(run.live).toBe(false);
    expect(gate.begin().live).toBe(false);
    expect(gpu.gate().begin().live).toBe(false);
    expect(part.dispose).toHaveBeenCalledOnce();
    expect(fake.evaluators[0].dispose).toHaveBeenCalledOnce();
    expect(fake.context.dispose).toHaveBeenCalledOnce();
    expect(gpu.ready).toBe(false);
    fake.lose();
    expect(onChange).not.toHaveBeenCalled(); // its listeners are gone
  });
});
