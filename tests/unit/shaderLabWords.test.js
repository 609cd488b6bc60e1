// The shader lab's words come from the catalogue ("shader-lab"; the exercises' titles are the
// exercise control's options): in the pseudo-locale nothing the lab writes has a word outside the
// brackets, while the driver's log and the student's code are kept as they were.
import { describe, expect, it, vi } from 'vitest';
import { createShaderLabRuns } from '../../src/panels/shader-lab/runs.js';
import {
  codeErrors, criteriaRows, describeText, mapLabel, mapMessage, mapTitle, noteText, readBackWords, spheresLabel, spheresMessage, summaryText,
} from '../../src/panels/shader-lab/words.js';
import { EXERCISES, criterion, exerciseById, exerciseMetal } from '../../src/panels/shader-lab/exercises.js';
import { EXERCISE_IDS } from '../../src/panels/shader-lab/exerciseIds.js';
import { conductorCases, dielectricCases } from '../../src/panels/shader-lab/gradingCases.js';
import { errorSummary, gradeCriterion } from '../../src/panels/shader-lab/gradeExercise.js';
import { checkStudentCode, readCompileLog } from '../../src/panels/shader-lab/studentShader.js';
import { createReadBackGpu } from '../../src/panels/shared/createReadBackGpu.js';
import { GpuFloatUnavailable } from '../../src/gl/evaluateMethodsGpu.js';
import { ShaderError } from '../../src/gl/shaderError.js';
import { methodsOfKind } from '../../src/methods/methods.js';
import { fakeGpu, HALF_PRECISION } from './fakeGpu.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

const clean = (text) => expect(wordsOutside(text), text).toBe('');

describe('the shader lab\'s exercises', () => {
  it('the schema offers every exercise, in the exercises\' order', () => {
    expect(EXERCISE_IDS).toEqual(EXERCISES.map((e) => e.id));
  });
});

describe('shader lab words in another language', () => {
  usePseudoLocale();

  it('names every exercise and criterion, and gives every grading reason, from the catalogue', () => {
    const dielectric = dielectricCases();
    const gold = conductorCases(exerciseMetal(exerciseById('gold')));
    for (const exercise of EXERCISES) {
      clean(exercise.title);
      const cases = exercise.kind === 'conductor' ? gold : dielectric;
      const answers = exercise.kind === 'conductor'
        ? [Float32Array.from(cases.flatMap((c) => c.exact)), Float32Array.from(cases.flatMap((c, i) => c.exact.map((v) => (i % 5 ? v : 1.5))))]
        : [
          ...methodsOfKind('dielectric').map((m) => Float32Array.from(cases, (c) => m.evaluate('fp32', c.cos, c.nI, c.nT))),
          Float32Array.from(cases, (c) => c.exact), Float32Array.from(cases, (c) => c.schlick),
        ];
      for (const id of exercise.criteria) {
        clean(criterion(id).label);
        for (const values of answers) clean(gradeCriterion(criterion(id), cases, values).reason);
      }
      clean(errorSummary(cases, answers[1]).where);
    }
    clean(gradeCriterion({ ...criterion('tir'), select: () => false }, dielectric, new Float32Array(dielectric.length)).reason);
  });

  it('refuses code in the catalogue\'s words, and keeps the driver\'s', () => {
    for (const code of ['', 'for (;;) {}\n#define x\nprecision highp float;\nx \\\n', 'x'.repeat(7000)]) {
      for (const { message } of checkStudentCode(code)) clean(message);
    }
    const log = readCompileLog("ERROR: 0:3: 'c' : undeclared\nERROR: 0:10005: syntax error\nERROR: 0:10009: 'x' : no match\n", 'float f()');
    expect(log[0]).toEqual({ line: 3, message: "'c' : undeclared" });
    for (const { message } of log.slice(1)) clean(message);
    expect(log[2].message).toContain("'x' : no match");
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
