// A question that grades a number says how closely: "to 3 decimals", "to 0.1°", "within 2°". The
// words are the catalogue's and the tolerance the question's; this holds them to each other in every
// language, so a tolerance changed in the code cannot leave a prompt promising another.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { QUESTIONS } from '../../src/homework/questions.js';
import { questionParams } from '../../src/homework/gradeAnswer.js';

const catalogue = (lang) => JSON.parse(readFileSync(resolve(import.meta.dirname, `../../locales/${lang}.json`), 'utf8')).questions;

/**
 * The tolerance a prompt states, read from its words: N decimals is half a unit of the Nth decimal;
 * "to 0.1°" half a tenth of a degree; "within X" is X. null where it states none.
 */
const STATED = {
  en: [
    [/\bto (\d) decimals\b/i, (n) => 0.5 * 10 ** -Number(n)],
    [/\bto (0\.1)°/, (x) => Number(x) / 2],
    [/\bwithin (\d+(?:\.\d+)?)°?/, (x) => Number(x)],
  ],
  es: [
    [/\bcon (\d) decimales\b/i, (n) => 0.5 * 10 ** -Number(n)],
    [/\bcon precisión de (0[.,]1)°/, (x) => Number(x.replace(',', '.')) / 2],
    [/\bcon un margen de (\d+(?:[.,]\d+)?)°?/, (x) => Number(x.replace(',', '.'))],
  ],
};

function statedTolerance(lang, prompt) {
  const found = STATED[lang].map(([pattern, read]) => pattern.exec(prompt) && read(pattern.exec(prompt)[1])).filter((x) => x !== null);
  return found.length === 1 ? found[0] : found.length ? NaN : null; // two statements: ambiguous
}

/** The prompt in `lang` with the question's example numbers (the catalogue's text, its {…} filled plainly, with a point). */
function prompt(lang, q) {
  const params = { ...questionParams(q, 'example'), tolerance: q.tolerance };
  return catalogue(lang)[`${q.id}.prompt`].replace(/\{(\w+)\}/g, (_, name) => (name in params ? String(params[name]) : `{${name}}`));
}

describe('a graded number\'s prompt states the tolerance it is graded with', () => {
  const graded = QUESTIONS.filter((q) => typeof q.tolerance === 'number');

  it('covers every number and prediction question', () => {
    expect(graded.map((q) => q.kind).sort()).toEqual(QUESTIONS.filter((q) => q.kind !== 'choice').map((q) => q.kind).sort());
    expect(graded.length).toBeGreaterThan(10);
  });

  for (const lang of ['en', 'es']) {
    it(`in ${lang}`, () => {
      for (const q of graded) {
        const text = prompt(lang, q);
        const stated = statedTolerance(lang, text);
        expect(stated, `${q.id} (${lang}) states no tolerance: ${text}`).not.toBeNull();
        expect(stated, `${q.id} (${lang}): ${text}`).toBeCloseTo(q.tolerance, 12);
      }
    });
  }
});
