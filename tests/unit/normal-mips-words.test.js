// Every word the normal-mips panel writes from its pure parts comes from the catalogue: in the
// pseudo-locale each sentence, caption and name is bracketed, with no word left outside.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  builtWhere, busyText, chainProblemText, describeText, legendText, shimmerStoppedText, statusText, summaryText,
} from '../../src/panels/normal-mips/words.js';
import { verdict } from '../../src/panels/normal-mips/createErrorDistancePlot.js';
import { techniqueName } from '../../src/panels/normal-mips/techniqueName.js';
import { schema } from '../../src/panels/normal-mips/schema.js';
import { TECHNIQUES } from '../../src/normals/techniqueLayout.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';
import { setNumberLocale } from '../../src/ui/format.js';

const defaults = () => Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, spec.default]));
const bands = [{ level: 0, rmse: 0.1 }, { level: 1, rmse: 0.2 }];
const errors = Object.fromEntries(TECHNIQUES.map((id, i) => [id, { rmse: 0.01 * (i + 1), bands }]));

describe('the normal-mips panel in another language', () => {
  usePseudoLocale();

  it('names every technique and every reason for building on the page\'s thread', () => {
    for (const id of TECHNIQUES) {
      expect(techniqueName(id)).toMatch(/^⟦/);
      expect(wordsOutside(techniqueName(id))).toBe('');
    }
    for (const problem of [{ reason: 'noWorkers' }, { reason: 'workersNotStarted', detail: 'x' },
      { reason: 'workerFailed', detail: 'x' }, { reason: 'workerNotLoaded' }]) {
      expect(wordsOutside(chainProblemText(problem))).toBe('');
    }
    for (const workers of [0, 1, 3]) expect(wordsOutside(builtWhere(workers))).toBe('');
  });

  it('writes the line of key numbers, the legend, the captions and the description', () => {
    const facts = { built: { ms: 41.6, workers: 2, size: 256 }, maxAnisotropy: 4, floatLinear: false, problem: '' };
    const lines = [
      summaryText(defaults(), { ...facts, problem: chainProblemText({ reason: 'noWorkers' }) }),
      summaryText({ ...defaults(), anisotropy: '16', precision: 'f32' }, { ...facts, built: { ms: 0, workers: 0, size: 0 } }),
      summaryText({ ...defaults(), anisotropy: '4', level: 3 }, facts),
      legendText(defaults()),
      ...['split', 'technique', 'truth', 'difference'].flatMap((view) => [true, false].flatMap((truth) => {
        const { left, right, pending } = statusText({ ...defaults(), view, truth }, { samples: 64, cap: 128 });
        return [left, right, pending];
      })),
      statusText(defaults(), { samples: 128, cap: 128 }).pending,
      describeText({ ...defaults(), truth: false }, { errors: null, shimmer: null, plotNote: '' }),
      describeText({ ...defaults(), level: 2 }, { errors: null, shimmer: { toksvig: 0.001 }, plotNote: '' }),
      describeText(defaults(), { errors, shimmer: null, plotNote: verdict(errors, 'toksvig', [0, 1]) }),
      verdict(errors, 'naive', [0, 1]),
      verdict({ ...errors, naive: { rmse: 1, bands: [{ level: 0, rmse: 1 }, { level: 1, rmse: 1 }] } }, 'lean', [0, 1]),
      shimmerStoppedText('lost'),
    ];
    for (const line of lines) expect(wordsOutside(line), line).toBe('');
    expect(lines[0]).toMatch(/^⟦/);
  });

  it('says that the chains are building, and why a build failed', () => {
    expect(wordsOutside(busyText({ size: 256 }))).toBe('');
    const failed = busyText({ error: new RangeError('size must be a power of two') });
    expect(failed).toContain('size must be a power of two'); // the builder's own words, kept
    expect(wordsOutside(failed.replace('size must be a power of two', ''))).toBe('');
  });
});

describe('the normal-mips panel\'s numbers in a language that writes a decimal comma', () => {
  beforeAll(() => setNumberLocale('es'));
  afterAll(() => setNumberLocale('en'));

  it('writes base α and every other number with the comma', () => {
    const facts = { built: { ms: 41.6, workers: 2, size: 256 }, maxAnisotropy: 4, floatLinear: true, problem: '' };
    const line = summaryText({ ...defaults(), alpha: 0.215 }, facts);
    expect(line).toContain('base Beckmann α = 0,215 (Blinn-Phong s = ');
    expect(line).toContain('R0 = 0,040');
    expect(describeText({ ...defaults(), truth: false }, { errors: null, shimmer: null, plotNote: '' })).toContain('at base α = 0,2,');
    expect(legendText(defaults())).toBe('level 8 (difference: 0 to 0,25)');
  });
});
