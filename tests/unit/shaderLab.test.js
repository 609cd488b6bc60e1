import { describe, expect, it } from 'vitest';
import { deflateSync } from 'fflate';
import { caseInputs, conductorCases, dielectricCases } from '../../src/panels/shader-lab/gradingCases.js';
import { EXERCISES, criterion, exerciseMetal } from '../../src/panels/shader-lab/exercises.js';
import { errorSummary, gradeCriterion } from '../../src/panels/shader-lab/gradeExercise.js';
import { MAX_CODE, WRAPPER_LINE, checkStudentCode, readCompileLog, studentFragment } from '../../src/panels/shader-lab/studentShader.js';
import { MAX_BYTES, decodeCode } from '../../src/panels/shader-lab/codeCodec.js';
import { criticalAngle, fresnelConductor, fresnelExact } from '../../src/optics/fresnel.js';
import { methodById } from '../../src/methods/methods.js';

const cases = dielectricCases();

describe('the grading grid', () => {
  it('holds total internal reflection, the critical angle ± tiny steps, grazing, cos θ outside [0, 1] and matched indices', () => {
    const count = (pred) => cases.filter(pred).length;
    expect(count((c) => c.family === 'fromInside' && c.exact === 1)).toBeGreaterThan(100);
    expect(count((c) => c.tag === 'critical')).toBe(4 * 8);
    const glass = cases.filter((c) => c.tag === 'critical' && c.nI === 1.5 && c.nT === 1);
    const thetaC = (criticalAngle(1.5, 1) * 180) / Math.PI;
    expect(glass.map((c) => Math.abs(c.thetaDeg - thetaC)).sort((a, b) => a - b)[0]).toBeCloseTo(1e-5, 12);
    expect(count((c) => c.cos === 0)).toBe(12); // θ = 90° exactly, every pair
    expect(count((c) => c.cos > 1)).toBeGreaterThan(0);
    expect(count((c) => c.cos < 0)).toBeGreaterThan(0);
    expect(cases.filter((c) => c.family === 'matched').every((c) => c.exact === 0)).toBe(true);
  });
  it('rounds inputs to float32 and takes the reference at those inputs, cos θ clamped', () => {
    for (const c of cases) {
      expect(Math.fround(c.cos)).toBe(c.cos);
      expect(c.exact).toBe(fresnelExact(Math.min(1, Math.max(0, c.cos)), c.nI, c.nT));
    }
    const gold = conductorCases(exerciseMetal(EXERCISES.find((e) => e.id === 'gold')));
    expect(gold[0].exact[0]).toBe(fresnelConductor(1, Math.fround(0.156), Math.fround(3.602)));
    const { inputs, extra } = caseInputs(gold);
    expect(inputs.length).toBe(gold.length * 4);
    expect(Array.from(extra.subarray(0, 3))).toEqual(gold[0].k);
  });
});

describe('criteria', () => {
  const exactValues = Float32Array.from(cases, (c) => c.exact);
  it('the core itself passes every dielectric criterion; each criterion checks some cases', () => {
    for (const exercise of EXERCISES.filter((e) => e.kind === 'dielectric')) {
      for (const id of exercise.criteria) {
        const crit = criterion(id);
        const values = crit.target === 'schlick' ? Float32Array.from(cases, (c) => c.schlick) : exactValues;
        const graded = gradeCriterion(crit, cases, values);
        expect(graded.checked, id).toBeGreaterThan(0);
        expect(graded.pass, `${id}: ${graded.code}`).toBe(true);
      }
    }
  });
  it('known-wrong functions fail the criterion that names their fault, with that case and its numbers', () => {
    const emulate = (methodId) => Float32Array.from(cases, (c) => methodById(methodId).evaluate('fp32', c.cos, c.nI, c.nT));
    // The lecture's order 1 + c² − m²: matched indices near grazing come out 1 instead of 0.
    const literal = gradeCriterion(criterion('matched'), cases, emulate('exact-cg-literal'));
    expect(literal).toMatchObject({ id: 'matched', pass: false, code: 'aboveTolerance', target: 'exact', tolerance: 1e-3 });
    expect(literal.worst).toMatchObject({ kind: 'aboveTolerance', reference: 0, channel: null, case: { family: 'matched' } });
    expect(literal.worst.value).toBeCloseTo(1, 4);
    expect(literal.worst.error).toBe(literal.worst.value);
    expect([89.99, 90]).toContain(literal.worst.case.thetaDeg);
    // Schlick on cos θi has no total internal reflection.
    const schlick = gradeCriterion(criterion('tir'), cases, emulate('schlick-pow'));
    expect(schlick).toMatchObject({ pass: false, code: 'aboveTolerance', worst: { reference: 1, case: { family: 'fromInside' } } });
    expect(schlick.worst.case.thetaDeg).toBeGreaterThan(schlick.worst.case.critical);
    // pow(1 − c, 5) without a clamp: NaN for cos θ above 1 (pow of a negative base, GLSL ES §8.2),
    // named at the smallest step past 1.
    const unclamped = gradeCriterion(criterion('schlickClamped'), cases, emulate('schlick-pow'));
    expect(unclamped).toMatchObject({ pass: false, code: 'notFinite', worst: { kind: 'notFinite', case: { thetaDeg: null } } });
    expect(unclamped.worst.value).toBeNaN();
    expect(unclamped.worst.case.cos).toBe(1 + 2 ** -23);
    expect(unclamped.failed).toBeGreaterThan(0);
    expect(unclamped.failed).toBeLessThan(unclamped.checked);
  });
  it('says how a criterion passes: all within its tolerance, all sane, or no case at all', () => {
    const exact = gradeCriterion(criterion('exactFromAir'), cases, exactValues);
    expect(exact).toMatchObject({ pass: true, code: 'allWithin', failed: 0 });
    expect(exact.worst.error).toBeLessThanOrEqual(2 ** -24); // the largest difference: float32's rounding of R ≤ 1
    expect(gradeCriterion(criterion('nearCritical'), cases, exactValues)).toMatchObject({ pass: true, code: 'allSane' });
    const none = gradeCriterion({ ...criterion('tir'), select: () => false }, cases, exactValues);
    expect(none).toMatchObject({ pass: false, code: 'noCase', checked: 0, worst: null });
  });
  it('sums up the error with the worst case named, NaN counted as infinite', () => {
    const values = Float32Array.from(cases, (c) => c.exact);
    values[5] = NaN;
    const summary = errorSummary(cases, values);
    expect(summary.max).toBe(Infinity);
    expect(summary.worst.case).toBe(cases[5]);
    expect(summary.worst.value).toBeNaN();
    expect(errorSummary(cases, cases.map((c) => c.exact)).max).toBe(0);
  });
});

describe('the student\'s code in the page\'s shader', () => {
  it('is refused with a line when it loops or changes the wrapper, and not for words in comments', () => {
    expect(checkStudentCode('float fresnel(float c, float a, float b) {\n  for (int i = 0; i < 9; i++) {}\n  return 0.0;\n}'))
      .toEqual([{ line: 2, code: 'loop' }]);
    expect(checkStudentCode('#version 100\nfloat x;')).toEqual([{ line: 1, code: 'directive' }]);
    expect(checkStudentCode('// do not loop: for, while\n/* while\n */ float f() { return 1.0; }')).toEqual([]);
    expect(checkStudentCode('x'.repeat(7000))).toEqual([{ line: null, code: 'tooLong', length: 7000, max: MAX_CODE }]);
    expect(checkStudentCode('#define F(a, b) a##b\nfloat f() { F(fo, r) (;;) {} return 1.0; }')[0]).toEqual({ line: 1, code: 'directive' });
    // Ways a loop could hide from a simpler check: a // comment holding /*, a line continuation,
    // lines ended by \r alone.
    const loopAt2 = [{ line: 2, code: 'loop' }];
    expect(checkStudentCode('float f() { // /*\n  while (true) {}\n  return 0.0; // */\n}')).toEqual(loopAt2);
    expect(checkStudentCode('float f() {\n  wh\\\nile (true) {}\n  return 0.0;\n}')).toEqual([{ line: 2, code: 'continuation' }]);
    expect(checkStudentCode('float f() { // note\r  while (true) {}\r  return 0.0;\r}')).toEqual(loopAt2);
    expect(checkStudentCode('precision highp float;\nfloat f() { highp float x = 1.0; return x; }')).toEqual([{ line: 1, code: 'precision' }]);
    expect(checkStudentCode('  ')).toEqual([{ line: null, code: 'noCode' }]);
  });
  it('sits after #line 1, so the driver names the student\'s lines; the wrapper\'s lines are told apart', () => {
    const source = studentFragment('float fresnel(float c, float a, float b) { return c; }', { precision: 'mediump' });
    expect(source).toMatch(/^#version 300 es\nprecision mediump float;/);
    expect(source).toContain(`#line 1\nfloat fresnel`);
    expect(source).toContain(`#line ${WRAPPER_LINE}\nvoid main()`);
    const log = "ERROR: 0:3: 'g' : undeclared identifier\nERROR: 0:3: '=' : dimension mismatch\n"
      + "ERROR: 0:10003: 'fresnel' : no matching overloaded function found\nERROR: 3 compilation errors.  No code generated.\n\n\u0000";
    expect(readCompileLog(log)).toEqual([
      { line: 3, code: 'driver', text: "'g' : undeclared identifier" },
      { line: 3, code: 'driver', text: "'=' : dimension mismatch" },
      { line: null, code: 'missingFunction', text: "'fresnel' : no matching overloaded function found" },
    ]);
    expect(readCompileLog('0(7) : error C0000: syntax error, unexpected identifier'))
      .toEqual([{ line: 7, code: 'driver', text: 'syntax error, unexpected identifier' }]);
    expect(readCompileLog("ERROR: 0:10001: 'void' : syntax error")).toEqual([{ line: null, code: 'afterLastLine', text: "'void' : syntax error" }]);
  });
});

describe('the code in the link', () => {
  it('is compact, round-trips, and a link not of the compact form is refused', async () => {
    const { encodeCode, decodeCode, useDeflate } = await import('../../src/panels/shader-lab/codeCodec.js');
    const { deflateSync } = await import('fflate');
    // Modules are shared between test files (isolate: false), and a file that imports the panel's
    // module has given deflate already: start from a page where it has not.
    useDeflate(null);
    expect(encodeCode('float x;')).toBe('float x;'); // before the panel gives deflate: plain text, which reads back
    useDeflate((bytes) => deflateSync(bytes, { level: 9 }));
    const { parseValue, formatValue } = await import('../../src/host/params.js');
    const { schema } = await import('../../src/panels/shader-lab/schema.js');
    const code = EXERCISES[1].reference;
    const compact = encodeCode(code);
    expect(compact).toMatch(/^\*[0-9a-z]+\.[A-Za-z0-9_-]+$/);
    expect(new URLSearchParams({ c: compact }).toString().length).toBeLessThan(new URLSearchParams({ c: code }).toString().length / 1.5);
    expect(decodeCode(compact)).toBe(code);
    expect(decodeCode(code)).toBe(code); // plain text, from a message
    expect(decodeCode('*AAAA$')).toBeNull(); // neither is of the form: no "." after the length
    expect(decodeCode(`*${'A'.repeat(20_000)}`)).toBeNull();
    expect(parseValue(schema.code, compact)).toEqual({ ok: true, value: code });
    expect(formatValue(schema.code, code)).toBe(compact);
    expect(parseValue(schema.code, '*garbage!')).toMatchObject({ ok: false });
    expect(parseValue(schema.code, 7)).toMatchObject({ ok: false });
    expect(parseValue(schema.code, 'x'.repeat(12_001))).toMatchObject({ ok: false, reason: expect.stringMatching(/longer than 12000/) });
  });

  // Codes of the right form, built here from fflate's raw DEFLATE with a length field of our choosing.
  describe('of the right form but damaged or oversized', () => {
    const utf8 = (text) => new TextEncoder().encode(text);
    const compact = (stream, length) => `*${length.toString(36)}.${Buffer.from(stream).toString('base64url')}`;
    const code = utf8(EXERCISES[1].reference);

    it('reads back when nothing is altered, up to the length cap', () => {
      expect(decodeCode(compact(deflateSync(code), code.length))).toBe(EXERCISES[1].reference);
      const longest = utf8('x'.repeat(MAX_BYTES));
      expect(decodeCode(compact(deflateSync(longest), MAX_BYTES))).toHaveLength(MAX_BYTES);
    });
    it('is refused past the length cap before it is inflated, and at a length of 0', () => {
      // A valid stream of MAX_BYTES + 1 bytes, stated truly: about 90 characters of link.
      const over = utf8('x'.repeat(MAX_BYTES + 1));
      expect(decodeCode(compact(deflateSync(over), over.length))).toBeNull();
      expect(decodeCode(compact(deflateSync(new Uint8Array(0)), 0))).toBeNull();
    });
    it('is refused when its stream runs past its stated length or stops short of it', () => {
      const stream = deflateSync(code);
      for (const length of [code.length - 1, code.length - 100, 1, code.length + 1]) {
        expect(decodeCode(compact(stream, length)), `stated ${length}`).toBeNull();
      }
    });
    it('is refused when its stream is bad: a reserved block type, cut short, or not UTF-8', () => {
      const reserved = deflateSync(code);
      reserved[0] |= 0b110; // BTYPE 11, reserved (RFC 1951 §3.2.3)
      expect(decodeCode(compact(reserved, code.length))).toBeNull();
      expect(decodeCode(compact(deflateSync(code).subarray(0, 20), code.length))).toBeNull();
      expect(decodeCode(compact(deflateSync(new Uint8Array([0x66, 0xff, 0xfe])), 3))).toBeNull();
    });
  });
});
