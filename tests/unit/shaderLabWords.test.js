// The shader lab's words come from the catalogue ("shader-lab"; the exercises' titles are the
// exercise control's options), and say what the runs keep as codes and numbers: in English as the
// lab means them, in the pseudo-locale with no word outside the brackets (the driver's log and
// the student's code kept as they were), and in Spanish with every number's decimal comma.
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import spanish from 'virtual:messages/es';
import { createShaderLabRuns } from '../../src/panels/shader-lab/runs.js';
import {
  caseText, codeErrors, criteriaRows, criterionLabel, describeText, exerciseTitle, mapLabel, mapMessage, mapTitle, noteText,
  problemText, readBackWords, reasonText, spheresLabel, spheresMessage, summaryText, whereText,
} from '../../src/panels/shader-lab/words.js';
import { EXERCISES, criterion, exerciseById, exerciseMetal } from '../../src/panels/shader-lab/exercises.js';
import { EXERCISE_IDS } from '../../src/panels/shader-lab/exerciseIds.js';
import { conductorCases, dielectricCases } from '../../src/panels/shader-lab/gradingCases.js';
import { errorSummary, gradeCriterion } from '../../src/panels/shader-lab/gradeExercise.js';
import { MAX_CODE, checkStudentCode, readCompileLog } from '../../src/panels/shader-lab/studentShader.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { methodsOfKind } from '../../src/methods/methods.js';
import { setCatalogue } from '../../src/i18n/messages.js';
import { setNumberLocale } from '../../src/ui/format.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

const f = Math.fround;
/** A dielectric case as gradingCases.js makes one (the numbers here are written out, not computed by the lab). */
const dielectric = (cos, nI, nT, thetaDeg, tag = thetaDeg === null ? 'outside' : 'sweep') => ({
  cos: f(cos), nI: f(nI), nT: f(nT), thetaDeg, family: 'fromAir', tag, critical: null, exact: 0, schlick: 0,
});
const WATER_HEAD_ON = dielectric(1, 1, 1.33, 0);
/** R = 1 everywhere, graded on exactFromAir: head-on into water is farthest from the exact R. */
const ONES_FROM_AIR = {
  id: 'exactFromAir', precision: 'highp', target: 'exact', tolerance: 1e-5, code: 'aboveTolerance', pass: false, checked: 546, failed: 543,
  worst: { kind: 'aboveTolerance', case: WATER_HEAD_ON, channel: null, value: 1, reference: 0.0200593, error: 0.9799407 },
};
const EXACT = exerciseById('exact');

describe('shader lab words in English', () => {
  it('says a criterion\'s result from its code and numbers, naming its worst case', () => {
    expect(reasonText(ONES_FROM_AIR))
      .toBe('1.0000 where the exact R is 0.0201 (off by 0.9799, more than 0.00001) at θ = 0.00°, n_i 1 → n_t 1.33; 543 of 546 fail.');
    const aboveOne = dielectric(1 + 2 ** -23, 1, 1.5, null);
    const nan = { kind: 'notFinite', case: aboveOne, channel: null, value: NaN, reference: 0.04, error: NaN };
    expect(reasonText({ ...ONES_FROM_AIR, code: 'notFinite', target: 'schlick', checked: 18, failed: 9, worst: nan }))
      .toBe('NaN at cos θ = 1.0000001, n_i 1 → n_t 1.5 (9 of 18 fail).');
    const gold = { cos: f(0.0001745), n: [0.16, 0.43, 1.38], k: [3.6, 2.5, 1.9], thetaDeg: 89.99, family: 'metal', tag: 'grazing', critical: null, exact: [1, 1, 1] };
    const red = { kind: 'outOfRange', case: gold, channel: 'red', value: 1.5, reference: 0.99, error: 0.51 };
    expect(reasonText({ ...ONES_FROM_AIR, code: 'outOfRange', tolerance: 1e-4, checked: 561, failed: 3, worst: red }))
      .toBe('1.5000, outside [0, 1], at θ = 89.99000° (red) (3 of 561 fail).');
    const close = { kind: 'fine', case: dielectric(0.745, 1.5, 1, 41.81), channel: null, value: 0.5, reference: 0.5, error: 3e-8 };
    expect(reasonText({ ...ONES_FROM_AIR, code: 'allWithin', pass: true, failed: 0, worst: close }))
      .toBe('All 546 values within 0.00001 of the exact R; the largest difference 3.0e−8, at θ = 41.81°, n_i 1.5 → n_t 1.');
    expect(reasonText({ ...ONES_FROM_AIR, code: 'allSane', target: 'sane', tolerance: null, pass: true, failed: 0, worst: close }))
      .toBe('All 546 values finite and in [0, 1].');
    expect(reasonText({ ...ONES_FROM_AIR, code: 'noCase', checked: 0, failed: 0, worst: null })).toBe('No case to check.');
  });

  it('writes cos θ outside [0, 1] as the shortest decimal of its float32, a tiny one in e-notation', () => {
    expect(caseText(dielectric(1 + 1e-6, 1, 1.33, null))).toBe('cos θ = 1.000001, n_i 1 → n_t 1.33');
    expect(caseText(dielectric(-1e-3, 1.5, 1, null))).toBe('cos θ = −0.001, n_i 1.5 → n_t 1');
    expect(caseText(dielectric(-1e-7, 1.333, 1.3331, null))).toBe('cos θ = −1e−7, n_i 1.333 → n_t 1.3331');
    expect(caseText(dielectric(0.7454, 1.5, 1, 41.81031, 'critical'))).toBe('θ = 41.81031°, n_i 1.5 → n_t 1');
    expect(whereText({ case: WATER_HEAD_ON, channel: 'blue' })).toBe('θ = 0.00°, n_i 1 → n_t 1.33 (blue)');
  });

  it('says what stopped the code from its code and line, and keeps the driver\'s words', () => {
    const error = new ShaderError({ stage: 'fragment', log: 'the driver said no' });
    const lab = {
      exercise: () => EXACT,
      state: {
        stalled: false,
        errors: [
          { line: 2, code: 'loop' }, { line: null, code: 'tooLong', length: 7000, max: MAX_CODE },
          { line: 3, code: 'driver', text: "'c' : undeclared identifier" }, { line: null, code: 'afterLastLine', text: "'void' : syntax error" },
          { line: null, code: 'missingFunction', text: "'fresnel' : no matching overloaded function found" },
          { line: null, code: 'refused', error },
        ],
      },
    };
    expect(codeErrors(/** @type {any} */ (lab))).toEqual([
      { line: 2, message: 'Loops are refused here: a Fresnel function needs none, and a loop that never ends would stall the graphics card.' },
      { line: null, message: `The code is 7000 characters long; a Fresnel function needs far fewer (at most ${MAX_CODE} here).` },
      { line: 3, message: "'c' : undeclared identifier" },
      { line: null, message: "After your last line: 'void' : syntax error (a missing } or ;?)." },
      {
        line: null,
        message: "Define float fresnel(float cosTheta, float nI, float nT): the page calls it ('fresnel' : no matching overloaded function found).",
      },
      { line: null, message: error.message },
    ]);
    expect(problemText({ line: 1, code: 'directive' }, EXACT)).toMatch(/^Preprocessor lines \(#…\) are refused here/);
    expect(problemText({ line: 1, code: 'continuation' }, EXACT)).toMatch(/^A backslash at the end of a line is refused here/);
    expect(problemText({ line: 1, code: 'precision' }, EXACT)).toMatch(/^Precision statements are refused here/);
    expect(problemText({ line: null, code: 'noCode' }, EXACT)).toBe('There is no code to compile.');
  });

  it('names the exercises and their criteria', () => {
    expect(exerciseTitle(EXACT)).toBe('Write the exact c/g form');
    expect(criterionLabel('tir')).toBe('From inside glass, water and diamond: R = 1 past the critical angle (from 0.001° past it)');
  });
});

describe('shader lab numbers in Spanish', () => {
  beforeAll(() => {
    setCatalogue('es', spanish);
    setNumberLocale('es');
  });
  afterAll(() => {
    setCatalogue('en', null);
    setNumberLocale('en');
  });

  it('writes each number of a case with the decimal comma, as the angles beside them', () => {
    expect(caseText(dielectric(0, 1.5, 1.33, 90))).toBe('θ = 90,00°, n_i 1,5 → n_t 1,33');
    expect(caseText(dielectric(1 + 2 ** -23, 1, 1.5, null))).toBe('cos θ = 1,0000001, n_i 1 → n_t 1,5');
    expect(caseText(dielectric(-1e-7, 1.333, 1.3331, null))).toBe('cos θ = −1e−7, n_i 1,333 → n_t 1,3331');
    for (const c of [...dielectricCases(), ...conductorCases(exerciseMetal(exerciseById('gold')))]) {
      expect(caseText(c)).not.toMatch(/\d\.\d/);
    }
  });

  it('says a reason in Spanish, every number in it with the comma', () => {
    expect(reasonText(ONES_FROM_AIR))
      .toBe('1,0000 donde la R exacta da 0,0201 (se desvía 0,9799, más de 0,00001) en θ = 0,00°, n_i 1 → n_t 1,33; fallan 543 de 546.');
  });
});

const clean = (text) => expect(wordsOutside(text), text).toBe('');

describe('the shader lab\'s exercises', () => {
  it('the schema offers every exercise, in the exercises\' order', () => {
    expect(EXERCISE_IDS).toEqual(EXERCISES.map((e) => e.id));
  });
});

describe('shader lab words in another language', () => {
  usePseudoLocale();

  it('names every exercise and criterion, and gives every grading reason, from the catalogue', () => {
    const dielectricAll = dielectricCases();
    const gold = conductorCases(exerciseMetal(exerciseById('gold')));
    for (const exercise of EXERCISES) {
      clean(exerciseTitle(exercise));
      const cases = exercise.kind === 'conductor' ? gold : dielectricAll;
      const answers = exercise.kind === 'conductor'
        ? [Float32Array.from(cases.flatMap((c) => c.exact)), Float32Array.from(cases.flatMap((c, i) => c.exact.map((v) => (i % 5 ? v : 1.5))))]
        : [
          ...methodsOfKind('dielectric').map((m) => Float32Array.from(cases, (c) => m.evaluate('fp32', c.cos, c.nI, c.nT))),
          Float32Array.from(cases, (c) => c.exact), Float32Array.from(cases, (c) => c.schlick),
        ];
      for (const id of exercise.criteria) {
        clean(criterionLabel(id));
        for (const values of answers) clean(reasonText(gradeCriterion(criterion(id), cases, values)));
      }
      clean(whereText(errorSummary(cases, answers[1]).worst));
    }
    clean(reasonText(gradeCriterion({ ...criterion('tir'), select: () => false }, dielectricAll, new Float32Array(dielectricAll.length))));
  });

  it('refuses code in the catalogue\'s words, and keeps the driver\'s', () => {
    for (const code of ['', 'for (;;) {}\n#define x\nprecision highp float;\nx \\\n', 'x'.repeat(7000)]) {
      for (const problem of checkStudentCode(code)) clean(problemText(problem, EXACT));
    }
    const log = readCompileLog("ERROR: 0:3: 'c' : undeclared\nERROR: 0:10005: syntax error\nERROR: 0:10009: 'x' : no match\n");
    expect(problemText(log[0], EXACT)).toBe("'c' : undeclared");
    for (const problem of log.slice(1)) clean(problemText(problem, EXACT));
    expect(problemText(log[2], EXACT)).toContain("'x' : no match");
    clean(problemText({ line: null, code: 'refused', error: new ShaderError({ stage: 'fragment', log: '' }) }, EXACT));
  });

  it('says the grade, the maps, the spheres and the GPU\'s problems in the catalogue\'s words', () => {
    const texts = [];
    const say = (runs, values) => {
      texts.push(summaryText(runs), noteText(runs), spheresMessage(runs), spheresLabel(runs), describeText(runs));
      for (const side of ['student', 'reference']) texts.push(mapTitle(values, side), mapMessage(runs, side), mapLabel(runs, side));
      for (const { label } of criteriaRows(runs)) texts.push(label);
    };
    const refusing = fakeGpu({
      evaluateSource: () => { throw new ShaderError({ stage: 'fragment', log: "ERROR: 0:3: 'c' : undeclared\n" }); },
    });
    for (const [values, fake] of [
      [{ exercise: 'exact', code: exerciseById('exact').reference }, fakeGpu()],
      [{ exercise: 'mediump' }, fakeGpu()], [{ exercise: 'gold' }, fakeGpu({ probe: HALF_PRECISION })],
      [{ exercise: 'exact', code: 'float fresnel(float c, float a, float b) { c = a; }' }, refusing],
      [{ exercise: 'schlick', code: 'while' }, fakeGpu()], [{ exercise: 'exact' }, fakeGpu({ evaluatorError: new GpuFloatUnavailable('⟦no float⟧') })],
    ]) {
      const painter = { paint: vi.fn(() => { throw new ShaderError({ stage: 'fragment', log: '' }); }), dispose: vi.fn() };
      const gpu = createReadBackGpu({ words: readBackWords, prepare: () => painter, ...fake.options() });
      const state = { code: '', precision: 'highp', homework: false, ...values };
      const runs = createShaderLabRuns({ values: state, gpu });
      runs.update();
      runs.paint(/** @type {any} */ ({}));
      say(runs, state);
      fake.lose();
      say(runs, state);
    }
    texts.push(readBackWords.unavailable, readBackWords.refused('ERROR: 0:1: x'));
    texts.push(codeErrors(/** @type {any} */ ({ state: { stalled: true, errors: [] } }))[0].message); // code held back after a stall
    for (const text of texts) clean(text);
  });
});
