// The emulation gap the speed-accuracy and stability panels state (src/methods/emulationGap.js),
// recomputed from the real-GPU run it cites; and the sentence on what mediump costs, from that run.
import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
import { EMULATION_GAP } from '../../src/methods/emulationGap.js';
import { deviceText, mediumpCostRatio } from '../../src/panels/speed-accuracy/words.js';

const run = JSON.parse(readFileSync(new URL('../../bench/gpu/results-h200-2026-12-04.json', import.meta.url), 'utf8'));
const EXACT = ['exact-cg', 'exact-cg-literal', 'exact-sp', 'conductor-exact'];

describe('the emulation gap', () => {
  it('is the range of read-back over emulated largest errors of the exact methods on the cited GPU', () => {
    expect(run.device.renderer).toContain(EMULATION_GAP.device);
    expect(run.date).toBe(EMULATION_GAP.date);
    const rows = run.speedAccuracy.methods.filter((m) => EXACT.includes(m.id));
    expect(rows).toHaveLength(EXACT.length);
    for (const [glsl, gpu, js] of [['highp', 'gpuHighp', 'fp32'], ['mediump', 'gpuMediump', 'fp16']]) {
      const ratios = rows.map((m) => m.error[gpu].max / m.error[js].max);
      const range = [Math.min(...ratios), Math.max(...ratios)].map((r) => Math.round(r * 10) / 10);
      expect(range, glsl).toEqual([...EMULATION_GAP[glsl]]);
    }
  });
});

describe('what mediump costs against highp, as measured', () => {
  it('is slower on the H200, by the sum of its methods\' medians', () => {
    const rows = run.speedAccuracy.methods;
    const sum = (key) => rows.reduce((total, m) => total + (key ? m.gpu[key] : m.gpu).nsPerEval.median, 0);
    expect(mediumpCostRatio(run.speedAccuracy)).toBeCloseTo(sum('mediump') / sum(null), 12);
    expect(mediumpCostRatio(run.speedAccuracy)).toBeGreaterThan(1.4); // every method was slower there
    expect(deviceText(run.speedAccuracy)).toContain('In mediump the methods took 1.48 times as long in all as in highp: '
      + 'on this GPU lower precision saves no time.');
    expect(mediumpCostRatio({ methods: [{ gpu: { nsPerEval: { median: 1 } } }] })).toBeNull(); // no mediump timing
  });
});
