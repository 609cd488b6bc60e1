// The stability panel's words come from the catalogue ("stability", and "methods" for the methods'
// and precisions' names): in the pseudo-locale no word it writes is outside the brackets.
import { describe, expect, it } from 'vitest';
import { createStabilityRuns } from '../../src/panels/stability/runs.js';
import {
  describeText, gpuMessage, mapLabel, noteText, pngCaption, readBackWords, readoutText, sideTitle,
} from '../../src/panels/stability/words.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

function setup(values, fake) {
  const gpu = createReadBackGpu({ words: readBackWords, ...fake.options() });
  const state = { method: 'schlick-pow', precision: 'mediump', tolerance: 0.001, ...values };
  const runs = createStabilityRuns({ values: state, gpu });
  runs.update();
  return { runs, state, fake };
}

/** Everything the panel says of its runs: the note, the maps' titles and names, the probe, the description, the caption. */
function said({ runs, state }) {
  const texts = [noteText(runs), gpuMessage(runs), describeText(state, runs), pngCaption(state, runs)];
  for (const side of ['gpu', 'js']) texts.push(sideTitle(runs.pair, side), mapLabel(state, runs, side) ?? '');
  for (const cell of [{ i: 60, j: 5 }, { i: 170, j: 100 }]) {
    runs.setProbe(cell);
    texts.push(readoutText(runs));
  }
  return texts;
}

describe('stability words in another language', () => {
  usePseudoLocale();

  it('says the maps, the probe and the description in the catalogue\'s words, on any GPU', () => {
    const cases = [
      setup({}, fakeGpu()), setup({ precision: 'fp64' }, fakeGpu({ probe: HALF_PRECISION })),
      setup({}, fakeGpu({ evaluatorError: new GpuFloatUnavailable('⟦no float targets⟧') })),
      setup({}, fakeGpu({ evaluate: () => { throw new RangeError('⟦too big⟧'); } })),
    ];
    const lost = setup({ method: 'exact-sp' }, fakeGpu());
    lost.fake.lose();
    lost.runs.update();
    cases.push(lost);
    for (const parts of cases) {
      for (const text of said(parts)) expect(wordsOutside(text), text).toBe('');
    }
    expect(wordsOutside(readBackWords.refused('ERROR: 0:1: x'))).toBe('');
    expect(wordsOutside(readBackWords.restartFailed(new Error('⟦out of memory⟧')))).toBe('');
  });
});
