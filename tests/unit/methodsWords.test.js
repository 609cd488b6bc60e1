// The words of src/methods come from the catalogue ("methods"): the methods', scenes', budgets'
// and precisions' names, the criterion and every sentence of the advisor's reason.
import { describe, expect, it } from 'vitest';
import { recommend } from '../../src/methods/advisor.js';
import { benchResults } from '../../src/methods/benchResults.js';
import { criterionText, DISPLAY_BUDGETS, recommendWithin } from '../../src/methods/displayBudgets.js';
import { recommendWithErrors } from '../../src/methods/gpuErrors.js';
import { BUDGET_IDS } from '../../src/methods/ids.js';
import { METHODS } from '../../src/methods/methods.js';
import { PRECISIONS } from '../../src/methods/rounding.js';
import { SCENES, sceneById } from '../../src/methods/scenes.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

describe('the words of src/methods in English', () => {
  it('a budget of one code is one code, of more codes codes', () => {
    const plastic = sceneById('plastic');
    expect(recommend(plastic, {}, { budgetCodes: 1 }).reason).toContain('stays under 1 8-bit code.');
    expect(recommend(plastic, {}, { budgetCodes: 2.55 }).reason).toContain('stays under 2.55 8-bit codes.');
  });
});

describe('the words of src/methods in another language', () => {
  usePseudoLocale();

  it('names every method, scene, budget and precision, and says the criterion, from the catalogue', () => {
    const names = [
      ...METHODS.flatMap((m) => [m.label, m.short]), ...SCENES.flatMap((s) => [s.label, s.inText, s.note]),
      ...DISPLAY_BUDGETS.map((b) => b.label), ...Object.values(PRECISIONS).map((p) => p.label), criterionText(),
    ];
    for (const name of names) {
      expect(name.startsWith('⟦')).toBe(true);
      expect(wordsOutside(name)).toBe('');
    }
  });

  it('gives every reason, for every scene and budget, in sentences of the catalogue', () => {
    for (const scene of SCENES) {
      for (const budget of BUDGET_IDS) {
        const { reason, criterion } = recommendWithin(scene, {}, budget);
        expect(wordsOutside(`${reason} ${criterion}`), `${scene.id}, ${budget}`).toBe('');
      }
    }
    const plastic = sceneById('plastic');
    const nothingPasses = recommend(plastic, {}, { budgetCodes: 1e-9 });
    expect(nothingPasses.invisible).toBe(false);
    expect(wordsOutside(nothingPasses.reason)).toBe('');
    const nan = Object.fromEntries(METHODS.filter((m) => m.kind === 'dielectric').map((m) => [m.id, {
      max: NaN, mean: NaN, rms: NaN, thetaAtMax: null, maxCodes: Infinity, meanCodes: Infinity, nanCount: 3, outOfRange: 0,
    }]));
    const failing = recommendWithErrors(plastic, nan, {}, { where: '⟦here⟧' });
    expect(failing.reason).toContain('3');
    expect(wordsOutside(failing.reason)).toBe('');
  });

  it('says where the costs of the results\' recommendations come from', () => {
    for (const { costSource } of Object.values(benchResults().recommendations)) expect(wordsOutside(costSource)).toBe('');
  });
});
