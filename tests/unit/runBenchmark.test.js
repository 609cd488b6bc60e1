// runBenchmark's parts stand in here, so what it does when one fails is seen without a GPU: a
// shader the GPU refuses is said in the results and the rest is still measured, while a cancelled
// run (the run gate aborts with a DOMException named AbortError, whose name is its prototype's)
// ends the benchmark there.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

const parts = vi.hoisted(() => ({
  gpu: vi.fn(),
  errors: vi.fn(),
  cpu: vi.fn(),
  frames: vi.fn(),
}));

vi.mock('../../src/gl/createContext.js', () => ({ createContext: () => ({ gl: {}, dispose: () => {} }) }));
vi.mock('../../src/gl/timeMethodsGpu.js', () => ({
  deviceInfo: () => ({ renderer: 'stand-in GPU', vendor: 'none', version: 'WebGL 2.0' }),
  timeMethodsGpu: parts.gpu,
}));
vi.mock('../../src/panels/speed-accuracy/measureGpuErrors.js', () => ({ gpuErrorsOn: parts.errors, rememberGpuErrors: () => {} }));
vi.mock('../../src/panels/speed-accuracy/timeCpu.js', () => ({ timeCpu: parts.cpu }));
vi.mock('../../src/panels/speed-accuracy/timeFrames.js', () => ({ timeFrames: parts.frames }));

// The unit tests share their workers' modules (isolate: false in vite.config.js): a file run before
// this one may have imported runBenchmark.js with its real parts, so it is imported again here.
vi.resetModules();
const { runBenchmark } = await import('../../src/panels/speed-accuracy/runBenchmark.js');

beforeEach(() => {
  vi.stubGlobal('document', { createElement: () => ({}) });
  vi.stubGlobal('navigator', { userAgent: 'a stand-in browser' });
  parts.errors.mockRejectedValue(new Error('no float render targets'));
  parts.cpu.mockResolvedValue({ methods: {}, where: 'page' });
  parts.frames.mockResolvedValue(null);
});
afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetAllMocks();
});

describe('runBenchmark when a part fails', () => {
  it('says a shader the GPU refuses in device.gpuError and still times the CPU', async () => {
    parts.gpu.mockRejectedValue(new Error('the driver refused the Schlick shader'));
    const results = await runBenchmark(/** @type {HTMLElement} */ ({}), { size: 'tiny' });
    expect(results.device.gpuError).toBe('the driver refused the Schlick shader');
    expect(results.device.gpuReadbackError).toBe('no float render targets');
    expect(parts.cpu).toHaveBeenCalledTimes(1);
  });

  it('ends at a cancelled GPU timing: the cancellation is thrown, not kept as the GPU\'s failure', async () => {
    const cancelled = new DOMException('Benchmark cancelled', 'AbortError');
    parts.gpu.mockRejectedValue(cancelled);
    await expect(runBenchmark(/** @type {HTMLElement} */ ({}), { size: 'tiny' })).rejects.toBe(cancelled);
    expect(parts.errors).not.toHaveBeenCalled();
    expect(parts.cpu).not.toHaveBeenCalled();
  });

  it('ends at a cancelled read-back too', async () => {
    const cancelled = new DOMException('The panel is gone', 'AbortError');
    parts.gpu.mockResolvedValue(null);
    parts.errors.mockRejectedValue(cancelled);
    await expect(runBenchmark(/** @type {HTMLElement} */ ({}), { size: 'tiny' })).rejects.toBe(cancelled);
    expect(parts.cpu).not.toHaveBeenCalled();
  });

  it('refuses a size it does not know, by its own keys', async () => {
    await expect(runBenchmark(/** @type {HTMLElement} */ ({}), { size: 'constructor' })).rejects.toThrow(RangeError);
    expect(parts.gpu).not.toHaveBeenCalled();
  });
});
