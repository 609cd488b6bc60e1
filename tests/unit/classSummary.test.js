// What the class got wrong per question (src/homework/class/summarizeQuestions.js): a card shows
// one student's instance, its prompt, options and explanations from the same numbers; and every
// answer is counted once, in the histogram and among the slips.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { gradeClassSync } from '../../src/homework/class/gradeClass.js';
import { buildGradebook } from '../../src/homework/class/buildGradebook.js';
import { summarizeQuestions } from '../../src/homework/class/summarizeQuestions.js';
import { syntheticClass } from '../../src/homework/class/syntheticClass.js';
import { questionParams } from '../../src/homework/gradeAnswer.js';
import { questionById } from '../../src/homework/questions.js';
import { makeHandIn } from '../../src/homework/sheetCodes.js';
import { check } from './fuzzConfig.js';

/** The first seed whose parameters for `question` pass `test` (chooses students, computes no answer). */
function seedWhere(question, test) {
  for (let i = 0; i < 1000; i += 1) if (test(questionParams(questionById(question), `seed${i}`))) return `seed${i}`;
  throw new Error(`no seed for ${question}`);
}
const summarize = (sheet, answers) => {
  const grades = gradeClassSync(sheet, answers.map(([seed, answer], i) => ({
    source: `${i}.json`, data: makeHandIn({ sheet, seed, name: `S${i}`, answers: [answer], time: '2026-01-01T00:00:00.000Z' }),
  })));
  if (!grades.ok) throw new Error(grades.problems.join(' '));
  return summarizeQuestions(grades, buildGradebook(grades))[0];
};

describe('one student\'s instance per card', () => {
  it('the misconception quotes the numbers of the metal in the prompt, not of another student\'s metal', () => {
    const sheet = { version: 1, title: 'Metals', items: [{ question: 'metal-grazing' }] };
    const gold = seedWhere('metal-grazing', (p) => p.metal === 'gold');
    const copper = seedWhere('metal-grazing', (p) => p.metal === 'copper');
    // Gold's student first (the card's instance) answers right; copper's takes "keeps its colour".
    const summary = summarize(sheet, [[gold, 'towards-white'], [copper, 'keeps-colour']]);
    expect(summary.shown).toEqual({ params: { metal: 'gold' }, sameForAll: false });
    const keeps = summary.options.find((o) => o.id === 'keeps-colour');
    expect(keeps.chosenWhenWrong).toBe(1);
    // Gold head-on, red, green, blue (the figures): 0.96, 0.79, 0.41; copper's are 0.94, 0.62, 0.54.
    expect(keeps.why).toMatch(/head-on the channels are 0\.96, 0\.79, 0\.41/);
    expect(keeps.why).not.toMatch(/0\.94, 0\.62, 0\.54/);
    expect(summary.options.find((o) => o.id === 'towards-white')).toMatchObject({ rightForShown: true, why: null });
  });
});

describe('every answer counted once', () => {
  // Water (n = 1.33): R(0°) = 0.0201, to 4 decimals (tolerance 0.00005).
  const sheet = { version: 1, title: 'R0', items: [{ question: 'r0-value' }] };
  const water = seedWhere('r0-value', (p) => p.nT === 1.33);

  it('a wrong answer a few per cent off stands as wrong in the ×1 column, apart from the right ones', () => {
    const summary = summarize(sheet, [[water, '0.0201'], [water, '0.0201'], [water, '0.0205']]);
    expect([summary.right, summary.wrong]).toEqual([2, 1]);
    const one = summary.ratio.bins.find((b) => b.lo <= 0 && 0 < b.hi);
    expect([one.count, one.right, one.wrong]).toEqual([3, 2, 1]);
  });

  it('an answer that fits a named slip and a factor is counted under the named slip only', () => {
    // 0.04 for water is "0.04, as if every material had it" and also about ×2.
    const summary = summarize(sheet, [[water, '0.0201'], [water, '0.04']]);
    expect(summary.slips.find((s) => s.label.startsWith('0.04')).count).toBe(1);
    expect(summary.ratio.labels.find((l) => l.text === '×2').count).toBe(0);
  });

  it('in any class: bins and what lies outside them add up to the answers, the slips to at most the wrong ones', () => {
    check(fc.property(fc.integer({ min: 1, max: 30 }), fc.string({ maxLength: 4 }), (students, seed) => {
      const made = syntheticClass({ students, questions: 12, seed: `once${seed}`, right: 0.4 });
      const grades = gradeClassSync(made.sheet, made.handIns);
      if (!grades.ok) throw new Error('not graded');
      for (const s of summarizeQuestions(grades, buildGradebook(grades))) {
        if (s.kind === 'choice') continue;
        const bins = s.kind === 'numeric' ? s.ratio.bins : s.offset.bins;
        for (const b of bins) expect(b.count).toBe(b.right + b.wrong);
        const inBins = bins.reduce((n, b) => n + b.count, 0);
        const right = bins.reduce((n, b) => n + b.right, 0);
        if (s.kind === 'predict') {
          expect([inBins, right]).toEqual([s.right + s.wrong, s.right]);
          continue;
        }
        const { below, above, opposite, zero, noRatio } = s.ratio;
        expect(inBins + below + above + opposite + zero + noRatio).toBe(s.right + s.wrong);
        const named = s.slips.reduce((n, x) => n + x.count, 0) + s.ratio.labels.reduce((n, x) => n + x.count, 0)
          + s.elsewhere.zero + s.elsewhere.opposite + s.elsewhere.far;
        expect(named).toBeLessThanOrEqual(s.wrong);
      }
    }), 20);
  });
});
