// The speed-accuracy panel's words come from the catalogue ("speed-accuracy", and "methods" for
// the methods, scenes and reasons): in the pseudo-locale no word of what it writes is left outside
// the brackets, whatever the costs, the error source and the GPU's problem.
import { describe, expect, it } from 'vitest';
import { describeView, speedAccuracyView, statusText } from '../../src/panels/speed-accuracy/words.js';
import { formatCodes, formatNs } from '../../src/panels/speed-accuracy/formatMeasures.js';
import { readBackProblem } from '../../src/panels/speed-accuracy/readBackProblem.js';
import { benchResults } from '../../src/methods/benchResults.js';
import { METHODS } from '../../src/methods/methods.js';
import { sceneById } from '../../src/methods/scenes.js';
import { WALL_TIMER } from '../../src/gl/timeMethodsGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';
import { offsetErrors } from './standInReadBack.js';

/** A run: every method timed on the GPU and the CPU, one of three timings noisy, frames timed, the GPU timing failed. */
function results() {
  const spread = (i) => (i % 3 ? { median: 10 + i, min: 9 + i, max: 11 + i } : { median: 10 + i, min: 1, max: 40 });
  const timed = Object.fromEntries(METHODS.map((m, i) => [m.id, { nsPerEval: spread(i), samples: [] }]));
  const frames = {
    width: 900, height: 300, ratio: 0.4, spheres: { msPerFrame: spread(1), pixels: 1, timer: WALL_TIMER },
    threePhysical: { msPerFrame: spread(2), pixels: 1 },
  };
  return benchResults({
    gpu: { results: { highp: timed, mediump: timed }, timer: WALL_TIMER }, cpu: { methods: timed }, frames,
    meta: { date: '2026-01-01T00:00:00Z', gpuError: '⟦refused⟧', device: { renderer: 'Stand-in' } },
  });
}

/** A read-back: each method off the reference by 1e-4 × (index + 1). */
function readBackOf(scene) {
  const errors = offsetErrors(scene);
  return { errors, device: { renderer: 'Stand-in' } };
}

const PROBES = [
  { probe: { mediumpIsFullPrecision: true, mediumpBits: 24 }, claimed: { mediump: { precision: 10 } } },
  { probe: { mediumpIsFullPrecision: false, mediumpBits: 11 }, claimed: null },
];

/** Every text a view holds for the page, the chart and the description. */
function texts(view, probe) {
  const { advice, chart, table } = view;
  return [
    advice.pickBefore, advice.pickAfter, advice.label, advice.reasonText, advice.criterionText,
    chart.xLabel, chart.yLabel, chart.title, chart.budget.label, chart.words.front, chart.words.nan, ...chart.points.map((p) => p.name),
    table.costHeader, table.captionText, view.device, view.sourceLine.text, view.gpuNote, describeView(view, probe),
  ];
}

describe('speed-accuracy words in another language', () => {
  usePseudoLocale();

  it('says the pick, the reason, the chart, the table and the description in the catalogue\'s words', () => {
    const run = results();
    for (const [sceneId, budget, cost, withRun] of [
      ['plastic', 'invisible', 'static', false], ['plastic', 'one-code', 'gpu', true], ['metal', 'acceptable', 'cpu', true],
      ['glass-inside', 'ten-percent', 'static', true],
    ]) {
      const scene = sceneById(sceneId);
      const sources = [
        { source: 'js', glsl: null, measured: null, waiting: null }, { source: 'js', glsl: null, measured: null, waiting: 'mediump' },
        ...(scene.kind === 'dielectric' ? [{ source: 'gpu-mediump', glsl: 'mediump', measured: readBackOf(scene), waiting: null }] : []),
      ];
      for (const [i, source] of sources.entries()) {
        const probe = PROBES[i % 2];
        const state = {
          source, results: withRun ? run : null, readBackError: null, probe,
        };
        const view = speedAccuracyView({ scene: sceneId, budget, errors: 'js', cost }, state);
        for (const text of texts(view, probe)) expect(wordsOutside(text), `${sceneId} ${budget} ${cost}: ${text}`).toBe('');
      }
    }
  }, 60_000); // every method emulated over four scenes

  it('says why the read-back failed, keeping the driver\'s line as it was', () => {
    const refused = readBackProblem(new ShaderError({ stage: 'fragment', log: "ERROR: 0:7: 'fm' : refused", label: '⟦pass⟧' }));
    expect(refused).toContain("ERROR: 0:7: 'fm' : refused");
    for (const text of [
      refused, readBackProblem(new GpuFloatUnavailable('⟦no float⟧')), readBackProblem(new ShaderError({ stage: 'link', log: '' })),
      readBackProblem(new Error('⟦lost⟧')), formatCodes(NaN), formatNs({ median: 1, min: 0.5, max: 2 }),
      statusText({ done: 2460 }), statusText({ cancelled: true }), statusText({ failed: new Error('⟦refused⟧') }),
    ]) expect(wordsOutside(text), text).toBe('');
  });
});
