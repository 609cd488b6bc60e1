// The shader lab's grader on this GPU: a student's function, wrapped by the page's read-back shader
// (studentShader.js), is evaluated over the grading grid (gradingCases.js) and graded against the
// float64 core (gradeExercise.js). Every reference answer passes every criterion of its exercise;
// the known-wrong answers of the lecture fail exactly the criterion that names their fault; a
// syntax error is reported at the student's own line.
import { test, expect, openLab } from './fixtures.js';
import { readBack } from './readBack.js';
import { caseInputs, conductorCases, dielectricCases } from '../../src/panels/shader-lab/gradingCases.js';
import { EXERCISES, exerciseById, exerciseMetal } from '../../src/panels/shader-lab/exercises.js';
import { gradeExercise } from '../../src/panels/shader-lab/gradeExercise.js';
import { readCompileLog, studentFragment } from '../../src/panels/shader-lab/studentShader.js';
import { reasonText } from '../../src/panels/shader-lab/words.js';

const casesFor = (exercise) => (exercise.kind === 'conductor' ? conductorCases(exerciseMetal(exercise)) : dielectricCases());

/** The student's code graded on this GPU: { criterion id → result }. */
async function grade(page, exercise, code) {
  const cases = casesFor(exercise);
  const { inputs, extra } = caseInputs(cases);
  const precisions = ['highp', 'mediump'];
  const width = 1024; // rows of 1024 texels: within WebGL2's guaranteed 2048
  const outputs = await readBack(page, {
    width,
    height: Math.ceil(cases.length / width),
    textures: { uInputs: Array.from(inputs), uExtra: Array.from(extra) },
    runs: precisions.map((precision) => ({ fragment: studentFragment(code, { kind: exercise.kind, precision }) })),
  });
  const channels = exercise.kind === 'conductor' ? 3 : 1;
  const values = Object.fromEntries(precisions.map((p, r) => [p, Float32Array.from({ length: cases.length * channels }, (_, i) => outputs[r][Math.floor(i / channels) * 4 + (i % channels)])]));
  return Object.fromEntries(gradeExercise(exercise, cases, (p) => values[p]).map((r) => [r.id, r]));
}

const LECTURE_ORDER = `float fresnel(float cosTheta, float nI, float nT) {
  float m = nI / nT;
  float c = m * cosTheta;
  float g = sqrt(1.0 + c * c - m * m);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - m * m) / (c * (g - c) + m * m);
  return 0.5 * a * a * (1.0 + b * b);
}`;
const SCHLICK_UNCLAMPED = `float fresnel(float cosTheta, float nI, float nT) {
  float r0 = pow((nT - nI) / (nT + nI), 2.0);
  return r0 + (1.0 - r0) * pow(1.0 - cosTheta, 5.0);
}`;

test.beforeEach(async ({ page }) => {
  await openLab(page, 'embed.html?panel=schlick'); // any page: the grader needs only WebGL2
});

test('every reference answer passes every criterion of its exercise on this GPU', async ({ page }) => {
  for (const exercise of EXERCISES) {
    const results = await grade(page, exercise, exercise.reference);
    for (const id of exercise.criteria) expect(results[id].pass, `${exercise.id} / ${id}: ${reasonText(results[id])}`).toBe(true);
  }
});

test('known-wrong answers fail the criterion that names their fault', async ({ page }) => {
  // The slide's 1 + c² − m²: right from air, wrong for matched indices at grazing.
  const lecture = await grade(page, exerciseById('exact'), LECTURE_ORDER);
  expect(lecture.exactFromAir.pass, reasonText(lecture.exactFromAir)).toBe(true);
  expect(lecture.matched.pass).toBe(false);
  // Schlick on cos θi in the total-internal-reflection exercise: no TIR.
  const schlick = await grade(page, exerciseById('tir'), exerciseById('schlick').reference);
  expect(schlick.tir.pass).toBe(false);
  expect(schlick.tir, reasonText(schlick.tir)).toMatchObject({ code: 'aboveTolerance', worst: { reference: 1 } });
  // pow(1 − c, 5) without a clamp: Schlick's formula itself is right, cos θ outside [0, 1] is not.
  // Above 1, pow of a negative base is undefined (GLSL ES 3.00 §8.2): NaN on many GPUs, a tiny
  // number on others (SwiftShader); below 0 every GPU gives more than 1.
  const unclamped = await grade(page, exerciseById('schlick'), SCHLICK_UNCLAMPED);
  expect(unclamped.schlickFromAir.pass, reasonText(unclamped.schlickFromAir)).toBe(true);
  expect(unclamped.schlickClamped.pass).toBe(false);
  const clamped = unclamped.schlickClamped;
  expect([['notFinite', 1 + 2 ** -23], ['outOfRange', Math.fround(-0.001)]], reasonText(clamped))
    .toContainEqual([clamped.code, clamped.worst.case.cos]);
  if (clamped.code === 'outOfRange') expect(clamped.worst.value).toBeGreaterThan(1);
});

test('a compile error is reported at the student\'s own line, and a missing function as such', async ({ page }) => {
  const logOf = (source) => page.evaluate((src) => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const shader = gl.createShader(gl.FRAGMENT_SHADER);
    gl.shaderSource(shader, src);
    gl.compileShader(shader);
    return gl.getShaderParameter(shader, gl.COMPILE_STATUS) ? '' : gl.getShaderInfoLog(shader);
  }, source);
  const broken = 'float fresnel(float cosTheta, float nI, float nT) {\n  float m = nI / nT;\n  float g = sqrt(1.0 - m * m + c * c);\n  return g;\n}';
  const errors = readCompileLog(await logOf(studentFragment(broken)));
  expect(errors.length).toBeGreaterThan(0);
  expect(errors[0]).toMatchObject({ line: 3, code: 'driver', text: expect.stringMatching(/'c'.*undeclared identifier/) });
  const missing = readCompileLog(await logOf(studentFragment('float fresnell(float a, float b, float c) { return a; }')));
  expect(missing.some((e) => e.line === null && e.code === 'missingFunction')).toBe(true);
});
