import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { hashSeed, newSeed, seededRandom } from '../../src/homework/seededRandom.js';
import { parseAnswer } from '../../src/homework/parseAnswer.js';
import { QUESTIONS, questionById } from '../../src/homework/questions.js';
import { gradeAnswer, questionParams, trueOption } from '../../src/homework/gradeAnswer.js';
import { readSheet } from '../../src/homework/readSheet.js';
import { gradeHandIn } from '../../src/homework/gradeHandIn.js';
import { sheetFromCode, sheetToCode } from '../../src/homework/sheetCodes.js';
import { PANEL_IDS } from '../../src/panels/manifest.js';
import { FIXED_PANEL_IDS } from './fixedPanelIds.js';
import { fresnelExact } from '../../src/optics/fresnel.js';
import { absError, brewsterDegrees, cosOfDegrees, criticalDegrees, dielectricR } from './oracle/fresnelOracle.js';


/** Every set of parameters a question can draw: each rng.pick tried with every entry in turn. */
function allParams(question) {
  const out = [];
  const path = []; // [index, length] per pick, in the order the question makes them
  for (;;) {
    let depth = 0;
    const rng = {
      pick: (list) => {
        if (depth === path.length) path.push([0, list.length]);
        return list[path[depth++][0]];
      },
    };
    out.push(question.params(rng));
    path.length = depth;
    while (path.length && ++path.at(-1)[0] === path.at(-1)[1]) path.pop();
    if (!path.length) return out;
  }
}

describe('seeded randomness', () => {
  it('the same seed gives the same numbers, another seed others', () => {
    const run = (seed) => Array.from({ length: 8 }, seededRandom(seed).next);
    expect(run('alice')).toEqual(run('alice'));
    expect(run('alice')).not.toEqual(run('bob'));
    for (const x of run('alice')) expect(x >= 0 && x < 1).toBe(true);
    expect(hashSeed('a')).not.toBe(hashSeed('b'));
  });
  it('picks spread over a list, and new seeds differ', () => {
    const rng = seededRandom('spread');
    const counts = [0, 0, 0, 0];
    for (let i = 0; i < 4000; i += 1) counts[rng.pick([0, 1, 2, 3])] += 1;
    for (const c of counts) expect(c).toBeGreaterThan(850);
    expect(newSeed()).toMatch(/^[a-z2-9]{8}$/);
    expect(newSeed()).not.toBe(newSeed());
  });
});

describe('typed answers', () => {
  it('reads numbers with a point or a comma, degrees and percentages', () => {
    expect(parseAnswer('0.042')).toEqual({ ok: true, value: 0.042 });
    expect(parseAnswer(' 0,042 ')).toEqual({ ok: true, value: 0.042 });
    expect(parseAnswer('56.3°', 'deg')).toEqual({ ok: true, value: 56.3 });
    expect(parseAnswer('56.3 degrees', 'deg')).toEqual({ ok: true, value: 56.3 });
    expect(parseAnswer('4.2 %', 'fraction').value).toBeCloseTo(0.042, 15);
    expect(parseAnswer('−0.5').value).toBe(-0.5);
  });
  it('refuses what is not a number or carries the wrong unit, with a reason', () => {
    for (const [text, unit] of [['', null], ['abc', null], ['4 %', 'deg'], ['56 rad', 'deg'], ['0.04°', 'fraction'], ['1.2.3', null]]) {
      const read = parseAnswer(text, unit);
      expect(read.ok, text).toBe(false);
      expect(read.reason.length).toBeGreaterThan(5);
    }
  });
});

describe('the questions', () => {
  it('cover every panel of the lecture, the central concepts two or three times', () => {
    for (const q of QUESTIONS) expect(PANEL_IDS, q.id).toContain(q.panel);
    const count = (panel) => QUESTIONS.filter((q) => q.panel === panel).length;
    // A panel added since may start without one: the composer offers only panels that have questions.
    for (const id of FIXED_PANEL_IDS) expect(count(id), id).toBeGreaterThan(0);
    for (const id of ['exact-fresnel', 'schlick', 'polarization', 'metals', 'normal-mips']) expect(count(id), id).toBeGreaterThanOrEqual(2);
    // The critical angle and R(0°) are asked on two panels each.
    for (const id of ['critical-angle', 'critical-predict', 'r0-value', 'r0-materials']) expect(questionById(id), id).toBeDefined();
    for (const kind of ['numeric', 'predict', 'choice']) expect(QUESTIONS.some((q) => q.kind === kind), kind).toBe(true);
    expect(new Set(QUESTIONS.map((q) => q.id)).size).toBe(QUESTIONS.length);
  });
  it('every choice question has exactly one true option for every parameter it can draw, and every option explains itself', () => {
    for (const q of QUESTIONS.filter((x) => x.kind === 'choice')) {
      for (const p of allParams(q)) {
        const seed = JSON.stringify(p);
        const options = q.options(p);
        expect(options.filter((o) => o.holds(p)), `${q.id} ${seed}`).toHaveLength(1);
        for (const o of options) expect(o.why(p).length).toBeGreaterThan(20);
        expect(q.prompt(p)).not.toContain('undefined');
      }
    }
  });
  it('numeric answers are the physics\' values, against the 50-digit oracle for every parameter a question draws', () => {
    const oracle = {
      'exact-r': (p) => dielectricR(cosOfDegrees(p.theta), 1, p.nT),
      'brewster-exact': (p) => brewsterDegrees(p.nI, p.nT),
      'critical-angle': (p) => criticalDegrees(p.nI, 1),
      'r0-value': (p) => dielectricR(1, 1, p.nT),
    };
    for (const [id, truth] of Object.entries(oracle)) {
      const q = questionById(id);
      // 1e-12: float64 rounding is ~1e-14 here (degrees up to 90), a wrong formula or unit far more.
      for (const p of allParams(q)) expect(absError(q.expected(p), truth(p)), `${id} ${JSON.stringify(p)}`).toBeLessThan(1e-12);
    }
    // A case worked by hand: glass (1.5) from air, head-on, is 0.04.
    expect(questionById('r0-value').expected({ nT: 1.5 })).toBeCloseTo(0.04, 15);
    for (const q of QUESTIONS.filter((x) => x.kind !== 'choice')) {
      for (const p of allParams(q)) {
        expect(Number.isFinite(q.expected(p)), q.id).toBe(true);
        expect(q.prompt(p)).not.toMatch(/undefined|NaN/);
      }
    }
  });
  it('a predicted angle is checked against the angle its curve marks', () => {
    const DEG = Math.PI / 180;
    for (const q of QUESTIONS.filter((x) => x.kind === 'predict')) {
      for (const p of allParams(q)) {
        const truth = q.expected(p);
        const { f, level } = q.curve(p);
        expect(truth > 0 && truth < 90, q.id).toBe(true);
        if (level !== undefined) expect(f(truth), q.id).toBeCloseTo(level, 9);
        // Nothing on a 0.01° grid lies higher than a refined maximum.
        if (q.id === 'schlick-worst') for (let t = 0; t <= 90; t += 0.01) expect(f(t)).toBeLessThanOrEqual(f(truth) + 1e-15);
      }
    }
    const at = (id, p) => questionById(id).expected(p);
    expect(at('brewster-predict', { nT: 1.5 })).toBeCloseTo(56.3099, 4);
    expect(questionById('brewster-predict').curve({ nT: 1.5 }).f(at('brewster-predict', { nT: 1.5 }))).toBeLessThan(1e-20);
    expect(at('critical-predict', { nI: 1.5 })).toBeCloseTo(41.8103, 4);
    // Equal shares of sky and floor on water happen far out towards grazing (R(80°) is 0.35, R(85°) 0.58).
    const half = at('split-half', { nT: 1.333 });
    expect(half > 80 && half < 85).toBe(true);
    expect(fresnelExact(Math.cos(half * DEG), 1, 1.333)).toBeCloseTo(0.5, 12);
    expect(at('snell-angle', { theta: 30, nT: 1.5 })).toBeCloseTo(Math.asin(0.5 / 1.5) / DEG, 12);
    // Toksvig: |N_a| = 0.95, s = 64 gives s/(1 + s(1 − L)/L) = 64/(1 + 64·0.05/0.95).
    expect(at('toksvig-exponent', { L: 0.95, s: 64 })).toBeCloseTo(64 / (1 + (64 * 0.05) / 0.95), 12);
  });
  it('no prediction asks the student to use its panel, which stays hidden until every prediction is locked', () => {
    // buildQuestionCard shows a sheet's panels only once each prediction is committed (homework.card.panelWaits), and a
    // committed prediction cannot change: a prompt that sends the student to the panel asks for what cannot be done.
    const usesPanel = /\bhover|\bread-?out|\bdrag|\btap\b|\bslider|\bmeasure|lower the camera|the panel shows|\b(in|on) the panel\b/i;
    const usesPanelEs = /pasa el cursor|\blectura\b|arrastra|deslizador|\bmide\b|baja la cámara|el panel muestra|\ben el panel\b/i;
    const spanish = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../locales/es.json'), 'utf8')).questions;
    const predictions = QUESTIONS.filter((q) => q.kind === 'predict');
    expect(predictions.length).toBeGreaterThan(0);
    for (const q of predictions) {
      for (const p of allParams(q)) expect(q.prompt(p), q.id).not.toMatch(usesPanel);
      expect(spanish[`${q.id}.prompt`], q.id).not.toMatch(usesPanelEs);
    }
    // The words it looks for are the ones such a prompt uses.
    expect('Lower the camera and hover the road: the readout gives each spot\'s angle').toMatch(usesPanel);
    expect('Baja la cámara y pasa el cursor por la carretera: la lectura da el ángulo').toMatch(usesPanelEs);
  });
  it('each question\'s start state for its panel is valid there', async () => {
    const { applyParams, defaults } = await import('../../src/host/params.js');
    for (const q of QUESTIONS) {
      const { schema } = await import(`../../src/panels/${q.panel}/schema.js`);
      for (const p of allParams(q)) {
        const { rejected } = applyParams(schema, defaults(schema), q.state(p));
        expect(rejected, `${q.id} ${JSON.stringify(p)}`).toEqual([]);
      }
    }
  });
  it('two students usually get different numbers; one seed always the same', () => {
    const q = questionById('exact-r');
    expect(questionParams(q, 'alice')).toEqual(questionParams(q, 'alice'));
    const distinct = new Set(Array.from({ length: 20 }, (_, i) => JSON.stringify(questionParams(q, `student-${i}`))));
    expect(distinct.size).toBeGreaterThan(10);
  });
});

describe('grading', () => {
  it('right within the stated tolerance, wrong outside it, unreadable said so', () => {
    const q = questionById('exact-r');
    const p = { theta: 70, nT: 1.33 };
    const exact = fresnelExact(Math.cos((70 * Math.PI) / 180), 1, 1.33);
    expect(gradeAnswer(q, p, exact.toFixed(3)).correct).toBe(true);
    expect(gradeAnswer(q, p, (exact + 0.002).toFixed(3)).correct).toBe(false);
    expect(gradeAnswer(q, p, `${(exact * 100).toFixed(2)} %`).correct).toBe(true);
    expect(gradeAnswer(q, p, 'about a tenth')).toMatchObject({ answered: false, correct: false });
    const choice = questionById('metal-grazing');
    const cp = questionParams(choice, 'alice');
    expect(gradeAnswer(choice, cp, trueOption(choice, cp).id).correct).toBe(true);
    const wrong = gradeAnswer(choice, cp, 'keeps-colour');
    expect(wrong.correct).toBe(false);
    expect(wrong.explanation).toMatch(/^No:/);
  });
});

describe('sheets and handed-in files', () => {
  const sheet = { version: 1, title: 'Fresnel, week 3', items: [{ question: 'exact-r' }, { question: 'brewster-exact' }, { question: 'metal-grazing' }] };
  it('a good sheet reads; malformed ones are refused with reasons', () => {
    expect(readSheet(sheet)).toMatchObject({ ok: true, sheet: { reveal: 'after-answer' } });
    for (const bad of [null, [], 'sheet', { ...sheet, version: 2 }, { ...sheet, title: '' }, { ...sheet, items: [] },
      { ...sheet, items: [{ question: 'nope' }] }, { ...sheet, items: Array(41).fill({ question: 'exact-r' }) }, { ...sheet, reveal: 'never' }]) {
      const read = readSheet(bad);
      expect(read.ok).toBe(false);
      expect(read.problems.length).toBeGreaterThan(0);
    }
  });
  it('a sheet carries the language it was made in, through its code; any other lang is refused by name', () => {
    const spanish = { ...sheet, lang: 'es' };
    const read = readSheet(spanish);
    expect(read).toEqual({ ok: true, sheet: { ...spanish, reveal: 'after-answer' } });
    const back = sheetFromCode(sheetToCode(read.sheet));
    expect(readSheet(back.data)).toEqual(read);
    expect(readSheet({ ...sheet, lang: 'en-XA' }).sheet.lang).toBe('en-XA'); // the pseudo-locale the browser tests carry
    // A sheet made before sheets carried a language is read as it was: no lang is added, so its fingerprint stays.
    expect(Object.hasOwn(readSheet(sheet).sheet, 'lang')).toBe(false);
    for (const [bad, named] of [['fr', '“fr”'], ['ES', '“ES”'], ['', '“”'], [1, '“1”'], [['es'], '“(a list)”']]) {
      const refused = readSheet({ ...sheet, lang: bad });
      expect(refused.ok).toBe(false);
      expect(refused.problems).toEqual([`lang, where given, must be a language of the lab (en, es), not ${named}.`]);
    }
  });
  it('a handed-in file is graded by recomputation: a forged "correct" changes nothing', () => {
    const seed = 'x7k2m9qp';
    const answers = sheet.items.map(({ question }) => {
      const q = questionById(question);
      const p = questionParams(q, seed);
      return q.kind === 'choice' ? trueOption(q, p).id : q.expected(p).toFixed(4);
    });
    expect(gradeHandIn({ version: 1, sheet, seed, answers })).toMatchObject({ ok: true, score: 3, total: 3 });
    const forged = { version: 1, sheet, seed, answers: ['0.9', { value: '12', correct: true }, 'dark'], score: 3, correct: [true, true, true] };
    const graded = gradeHandIn(forged);
    expect(graded).toMatchObject({ ok: true, score: 0, total: 3 });
    // Another seed means other numbers: the same answers no longer fit.
    expect(gradeHandIn({ version: 1, sheet, seed: 'someone-else', answers }).score).toBeLessThan(3);
    for (const bad of [null, { sheet, seed, answers: [] }, { sheet, seed: '', answers }, { sheet: { title: 'x' }, seed, answers }]) {
      expect(gradeHandIn(bad).ok).toBe(false);
    }
  });
});
