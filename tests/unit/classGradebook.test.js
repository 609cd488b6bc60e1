// Grading a class, its gradebook and flags, sorting, CSV, what the class got wrong per question,
// and a class view saved and opened again (src/homework/class/).
import { describe, expect, it } from 'vitest';
import { gradeClass, gradeClassSteps, gradeClassSync } from '../../src/homework/class/gradeClass.js';
import { buildGradebook } from '../../src/homework/class/buildGradebook.js';
import { sortRows } from '../../src/homework/class/sortRows.js';
import { cellsToCsv, gradebookCells, gradebookToCsv, textCell } from '../../src/homework/class/gradebookToCsv.js';
import { summarizeQuestions } from '../../src/homework/class/summarizeQuestions.js';
import { readClassFile, writeClassFile } from '../../src/homework/class/classFile.js';
import { buildClassView } from '../../src/homework/class/buildClassView.js';
import { syntheticClass } from '../../src/homework/class/syntheticClass.js';
import { serveClassView } from '../../src/homework/class/classWorker.js';
import { questionParams } from '../../src/homework/gradeAnswer.js';
import { rightAnswer } from './oracle/rightAnswers.js';
import { questionById } from '../../src/homework/questions.js';
import { formatValue } from '../../src/homework/formatAnswer.js';
import { makeHandIn } from '../../src/homework/sheetCodes.js';
import { normalIncidence } from '../../src/optics/fresnel.js';

const sheet = { version: 1, title: 'Fresnel', items: ['exact-r', 'r0-value', 'snell-angle', 'brewster-predict', 'metal-grazing'].map((question) => ({ question })) };
const question = (i) => questionById(sheet.items[i].question);
const params = (seed, i) => questionParams(question(i), seed);

/** The right answer to item i for a seed (worked out apart from the lab), or a wrong one: the true value times `factor`. */
function answer(seed, i, how = 'right', factor = 2) {
  const q = question(i);
  const p = params(seed, i);
  if (how === 'none') return null;
  if (q.kind === 'choice') {
    const right = rightAnswer(q.id, p);
    return how === 'right' ? right : q.options(p).find((o) => o.id !== right).id;
  }
  const value = rightAnswer(q.id, p) * (how === 'right' ? 1 : factor);
  return q.kind === 'predict' ? Math.min(90, value) : formatValue(q, value);
}
const handIn = (name, seed, hows, more = {}) => ({
  source: `${name || 'someone'}.json`,
  data: makeHandIn({ sheet, seed, name, answers: hows.map((how, i) => answer(seed, i, how)), attempts: hows.map(() => 1), time: '2026-02-01T10:00:00.000Z', ...more }),
});
const ALL_RIGHT = ['right', 'right', 'right', 'right', 'right'];

describe('grading a class', () => {
  it('grades against the sheet set; another sheet, another class seed and data that is no hand-in are refused with the source', () => {
    const other = { ...sheet, title: 'Fresnel (edited)' };
    const seeded = { ...sheet, seed: 'class' };
    const handIns = [
      handIn('Ada', 's1', ALL_RIGHT),
      { source: 'edited.json', data: makeHandIn({ sheet: other, seed: 's2', name: 'Bo', answers: [null, null, null, null, null] }) },
      { source: 'sheet.json', data: sheet },
      { source: 'class.json', data: { kind: 'fresnel-lab-class', version: 1 } },
      { source: 'list.json [2]', data: [1, 2] },
      { source: 'short.json', data: { ...handIn('Cy', 's3', ALL_RIGHT).data, answers: ['1'] } },
    ];
    const grades = gradeClassSync(sheet, handIns);
    expect(grades.ok).toBe(true);
    expect(grades.graded.map((g) => [g.source, g.result.score])).toEqual([['Ada.json', 5]]);
    expect(Object.fromEntries(grades.refused.map((r) => [r.source, r.reason]))).toEqual({
      'edited.json': expect.stringMatching(/another sheet \(fingerprint \w+\) than the one given/),
      'sheet.json': expect.stringMatching(/a sheet, not a hand-in/),
      'class.json': expect.stringMatching(/saved class view/),
      'list.json [2]': 'A hand-in is a JSON object.',
      'short.json': expect.stringMatching(/one entry per question/),
    });
    const wrongSeed = gradeClassSync(seeded, [handIn('Ada', 's1', ALL_RIGHT, { sheet: seeded })]);
    expect(wrongSeed.refused[0].reason).toMatch(/gives everyone the seed class, but the file says s1/);
    expect(gradeClassSync({ title: 'no items' }, [])).toEqual({ ok: false, problems: expect.arrayContaining([expect.stringMatching(/^The sheet you set: /)]) });
  });

  it('runs in slices: the steps yield progress, and the async form pauses between them and can be stopped', async () => {
    const handIns = ['a', 'b', 'c', 'd'].map((name, i) => handIn(name, `s${i}`, ALL_RIGHT));
    const steps = gradeClassSteps(sheet, handIns, { sliceMs: 0 });
    const progress = [];
    let step = steps.next();
    for (; !step.done; step = steps.next()) progress.push(step.value);
    // First each question's first computation for each seed (done: 0), then a hand-in a step.
    expect(progress.filter((p) => p.done > 0)).toEqual([1, 2, 3].map((done) => ({ done, total: 4 })));
    expect(progress.filter((p) => p.done === 0).length).toBeGreaterThan(0);
    expect(progress.findIndex((p) => p.done > 0)).toBe(progress.filter((p) => p.done === 0).length);
    expect(step.value.graded).toHaveLength(4);
    const seen = [];
    let pauses = 0;
    const grades = await gradeClass(sheet, handIns, { sliceMs: 0, onProgress: (p) => seen.push(p.done), pause: async () => { pauses += 1; } });
    expect([seen.filter((done) => done > 0), pauses, grades.graded.length]).toEqual([[1, 2, 3], seen.length, 4]);
    const controller = new AbortController();
    const stopped = gradeClass(sheet, handIns, { sliceMs: 0, signal: controller.signal, onProgress: () => controller.abort(new Error('stopped')) });
    await expect(stopped).rejects.toThrow('stopped');
  });
});

describe('the gradebook', () => {
  it('a row per hand-in: score, percent, each question right, wrong or unanswered, tries, time and source', () => {
    const grades = gradeClassSync(sheet, [handIn('Ada', 's1', ['right', 'wrong', 'none', 'right', 'wrong'])]);
    const [row] = buildGradebook(grades).rows;
    expect(row).toMatchObject({ name: 'Ada', seed: 's1', score: 2, total: 5, percent: 40, marks: ['right', 'wrong', 'unanswered', 'right', 'wrong'], tries: [1, 1, 1, 1, 1], triesTotal: 5, time: '2026-02-01T10:00:00.000Z', source: 'Ada.json', counted: true, flags: [] });
  });

  it('the same name twice: the latest by time counts, the others are kept as superseded; equal times, the later in the list', () => {
    const grades = gradeClassSync(sheet, [
      handIn('Ada Lovelace', 's1', ALL_RIGHT, { time: '2026-02-02T10:00:00.000Z' }),
      handIn(' ada  lovelace ', 's1', ['wrong', 'right', 'right', 'right', 'right'], { time: '2026-02-01T10:00:00.000Z' }),
      handIn('Bo', 's2', ALL_RIGHT),
      handIn('Bo', 's2', ALL_RIGHT),
      handIn('Cy', 's3', ALL_RIGHT, { time: 'not a time' }),
      handIn('Cy', 's3', ALL_RIGHT),
    ]);
    const book = buildGradebook(grades);
    expect(book.rows.map((r) => r.counted)).toEqual([true, false, false, true, false, true]);
    expect([book.students, book.superseded]).toEqual([3, 3]);
    expect(book.rows[1].flags).toEqual([{ kind: 'superseded', text: expect.stringMatching(/handed in again later/), others: [0] }]);
    expect(book.rows[0].flags).toEqual([{ kind: 'resubmitted', text: 'Handed in 2 times; this one, the latest, counts.', others: [1] }]);
  });

  it('one seed under two names, identical wrong numbers from two students, no name, a seed other than the class seed', () => {
    const wrong = ['wrong', 'wrong', 'wrong', 'right', 'right'];
    const grades = gradeClassSync(sheet, [
      handIn('Bo', 'shared', wrong),
      handIn('Cy', 'shared', wrong),
      handIn('Di', 'own', wrong),
      { ...handIn('', 'x1', ALL_RIGHT), source: 'subs.zip/Eve Ng_99_assignsubmission_file_/h.json' },
    ]);
    const book = buildGradebook(grades);
    const kinds = book.rows.map((r) => r.flags.map((f) => f.kind));
    expect(kinds).toEqual([['shared-seed', 'copied'], ['shared-seed', 'copied'], [], ['no-name']]);
    expect(book.rows[0].flags[1].text).toMatch(/same wrong answers as Cy to the same numbers \(seed shared\) on questions 1, 2, 3/);
    // The rule is said with the flag: how many questions flag a pair, how many students make an answer a common slip.
    expect(book.rows[0].flags[1].text).toMatch(/Flagged at 3 or more such questions; a wrong answer that 4 or more students give is taken for a common slip/);
    expect(book.copiedRule).toEqual({ atLeast: 3, common: 4 });
    expect(book.rows[3].flags[0].text).toMatch(/the LMS's folder or file name says Eve Ng/);
    expect(book.rows[3].lmsName).toBe('Eve Ng');
    // Two wrong answers in common are not enough; a wrong answer most of the class shares is a common slip.
    const two = buildGradebook(gradeClassSync(sheet, [handIn('Bo', 'k', ['wrong', 'wrong', 'right', 'right', 'right']), handIn('Cy', 'k', ['wrong', 'wrong', 'right', 'right', 'right'])]));
    expect(two.rows[0].flags.map((f) => f.kind)).toEqual(['shared-seed']);
    const seeded = { ...sheet, seed: 'class' };
    const classGrades = gradeClassSync(seeded, [handIn('Ann', 'class', ALL_RIGHT, { sheet: seeded })]);
    classGrades.graded[0].result.seed = 'other'; // grades made some other way
    expect(buildGradebook(classGrades).rows[0].flags.map((f) => f.kind)).toEqual(['class-seed']);
  });
});

describe('sorting', () => {
  const row = (key, name, score, marks = [], time = null) => ({ key, name, lmsName: '', seed: 's', score, total: 5, percent: score * 20, marks, tries: [], triesTotal: null, time, source: `${name}.json`, counted: true, flags: [] });
  const rows = [row(0, 'Zoe', 3, ['right']), row(1, 'Student 10', 5, ['wrong']), row(2, 'Zoë', 3, ['unanswered'], '2026-01-02T00:00:00Z'), row(3, '', 4, ['right']), row(4, 'Student 9', 3, ['wrong'], '2026-01-01T00:00:00Z'), row(5, 'ada', 1)];
  const keys = (list) => list.map((r) => r.key);
  it('by name in the language\'s order, numbers in names as numbers, no name last either way; stable', () => {
    expect(keys(sortRows(rows, 'name', { locale: 'en' }))).toEqual([5, 4, 1, 0, 2, 3]);
    expect(keys(sortRows(rows, 'name', { locale: 'en', descending: true }))).toEqual([0, 2, 1, 4, 5, 3]);
  });
  it('by name under a language Intl refuses as the system reports it: English order, no error', () => {
    for (const locale of ['en-US@posix', 'C', 'en_US.UTF-8', '']) {
      expect(keys(sortRows(rows, 'name', { locale })), locale).toEqual([5, 4, 1, 0, 2, 3]);
    }
  });
  it('by score as numbers, ties in their order; by a question, unanswered last; by time, none last', () => {
    expect(keys(sortRows(rows, 'score'))).toEqual([5, 0, 2, 4, 3, 1]);
    expect(keys(sortRows(rows, 'score', { descending: true }))).toEqual([1, 3, 0, 2, 4, 5]);
    expect(keys(sortRows(rows, 'item:0'))).toEqual([1, 4, 0, 3, 2, 5]);
    expect(keys(sortRows(rows, 'item:0', { descending: true }))).toEqual([0, 3, 1, 4, 2, 5]);
    expect(keys(sortRows(rows, 'time', { descending: true }))).toEqual([2, 4, 0, 1, 3, 5]);
    expect(() => sortRows(rows, /** @type {any} */ ('constructor'))).toThrow(RangeError);
  });
});

describe('CSV', () => {
  it('UTF-8 with a byte-order mark, CRLF, RFC 4180 quoting, a column per question, points and percent', () => {
    const grades = gradeClassSync(sheet, [
      handIn('Zoë "Zo" Müller, Jr.', 's1', ['right', 'wrong', 'none', 'right', 'right']),
      handIn('=HYPERLINK("http://x","y")', 's2', ALL_RIGHT),
      handIn('-2+3', 's3', ALL_RIGHT, { time: '2026-02-02T10:00:00.000Z' }),
    ]);
    const csv = gradebookToCsv(buildGradebook(grades));
    expect(csv.startsWith('\ufeffName,LMS name,LMS user id,Seed,Score,Out of,Percent,Q1 exact-r,Q2 r0-value,Q3 snell-angle,Q4 brewster-predict,Q5 metal-grazing,Tries,Handed in,Counted,Flags,Source\r\n')).toBe(true);
    expect(csv.endsWith('\r\n')).toBe(true);
    expect(csv.split('\r\n')[1]).toBe('"Zoë ""Zo"" Müller, Jr.",,,s1,3,5,60.0,1,0,,1,1,5,2026-02-01T10:00:00.000Z,yes,,"Zoë ""Zo"" Müller, Jr..json"');
    expect(csv.split('\r\n')[2]).toMatch(/^"'=HYPERLINK\(""http:\/\/x"",""y""\)",/);
    expect(csv.split('\r\n')[3]).toMatch(/^'-2\+3,/);
    expect(csv.split('\r\n')).toHaveLength(5);
  });
  it('a semicolon form for spreadsheets that write 87,5: semicolons, a decimal comma, times in local time', () => {
    const time = '2026-02-01T10:05:00.000Z';
    const grades = gradeClassSync(sheet, [handIn('Zoë; Müller', 's1', ['right', 'wrong', 'none', 'right', 'right'], { time })]);
    const [head, line, end] = gradebookToCsv(buildGradebook(grades), { semicolons: true }).split('\r\n');
    expect(head).toBe('\ufeffName;LMS name;LMS user id;Seed;Score;Out of;Percent;Q1 exact-r;Q2 r0-value;Q3 snell-angle;Q4 brewster-predict;'
      + 'Q5 metal-grazing;Tries;Handed in (local time);Counted;Flags;Source');
    const at = new Date(time);
    const two = (n) => String(n).padStart(2, '0');
    const local = `${at.getFullYear()}-${two(at.getMonth() + 1)}-${two(at.getDate())} ${two(at.getHours())}:${two(at.getMinutes())}`;
    expect(line).toBe(`"Zoë; Müller";;;s1;3;5;60,0;1;0;;1;1;5;${local};yes;;"Zoë; Müller.json"`);
    expect(end).toBe('');
  });
  it('a cell that would start a formula gets an apostrophe; numbers we write and other text do not', () => {
    for (const text of ['=1+1', '+1', '-1', '@SUM(A1)', '\tx', '\rx', '＝1']) expect(textCell(text)).toBe(`'${text}`);
    for (const text of ['Ada', ' =1', '1-2', '', "'x"]) expect(textCell(text)).toBe(text);
    expect(cellsToCsv([['a\nb', 'c'], ['']])).toBe('\ufeff"a\nb",c\r\n\r\n');
  });
  it('superseded rows only on request, marked as not counted', () => {
    const grades = gradeClassSync(sheet, [handIn('Ada', 's1', ALL_RIGHT, { time: '2026-01-01T00:00:00Z' }), handIn('Ada', 's1', ALL_RIGHT)]);
    const book = buildGradebook(grades);
    expect(gradebookCells(book)).toHaveLength(2);
    expect(gradebookCells(book, { includeSuperseded: true }).map((r) => r[14])).toEqual(['Counted', 'no', 'yes']);
  });
});

describe('what the class got wrong', () => {
  it('a choice: each option\'s count and, for a wrong one, its misconception; a number: peaks at ×2 and at R(0°) for R; a prediction: offsets in 5° bins', () => {
    const seeds = ['a', 'b', 'c', 'd', 'e', 'f'];
    const handIns = seeds.map((seed, k) => {
      const hows = k < 2 ? ALL_RIGHT : ['wrong', 'wrong', 'none', 'wrong', 'wrong'];
      const h = handIn(`S${k}`, seed, hows);
      if (k === 5) h.data.answers[0] = formatValue(question(0), normalIncidence(1, params(seed, 0).nT)); // R(0°) for R(θ)
      if (k === 4) h.data.answers[2] = formatValue(question(2), (rightAnswer(question(2).id, params(seed, 2)) * Math.PI) / 180); // radians
      return h;
    });
    const grades = gradeClassSync(sheet, handIns);
    const summary = summarizeQuestions(grades, buildGradebook(grades));
    expect(summary.map((s) => [s.question, s.right, s.wrong, s.unanswered])).toEqual([
      ['exact-r', 2, 4, 0], ['r0-value', 2, 4, 0], ['snell-angle', 2, 1, 3], ['brewster-predict', 2, 4, 0], ['metal-grazing', 2, 4, 0],
    ]);
    expect(summary[0].shareRight).toBeCloseTo(1 / 3);
    const choice = summary[4].options;
    expect(choice.map((o) => o.id)).toEqual(['keeps-colour', 'towards-white', 'dark']);
    expect(choice.find((o) => o.id === 'towards-white')).toMatchObject({ chosen: 2, chosenWhenRight: 2, rightFor: 6, why: null });
    expect(choice.find((o) => o.id === 'keeps-colour')).toMatchObject({ chosen: 4, chosenWhenWrong: 4, rightFor: 0, why: expect.stringMatching(/^No: head-on the channels are/) });
    const { ratio, slips } = summary[0];
    const at = (x) => ratio.bins.find((b) => b.lo <= x && x < b.hi).count;
    expect(at(0)).toBe(2); // right
    expect(at(Math.log10(2))).toBe(3); // ×2
    expect(ratio.labels.find((l) => l.text === '×2').count).toBe(3);
    expect(slips.find((s) => s.label.startsWith('R(0°)')).count).toBe(1);
    expect(summary[2].ratio.labels.find((l) => l.text.startsWith('÷57.3')).count).toBe(1);
    expect(ratio.bins.reduce((n, b) => n + b.count, 0) + ratio.below + ratio.above + ratio.opposite + ratio.zero).toBe(6);
    const offsets = summary[3].offset;
    expect(offsets.bins).toHaveLength(37);
    expect(offsets.bins.find((b) => b.lo <= 0 && 0 < b.hi).count).toBe(2);
    expect(offsets.bins.reduce((n, b) => n + b.count, 0)).toBe(6);
  });
});

describe('a class view saved and opened', () => {
  it('opens as the same class, graded again; hostile or broken files are refused by name', () => {
    const handIns = [handIn('Ada', 's1', ALL_RIGHT), handIn('Bo', 's2', ['wrong', 'right', 'none', 'right', 'wrong'])];
    const text = writeClassFile({ sheet, handIns, saved: '2026-03-01T00:00:00.000Z' });
    const opened = readClassFile(text);
    expect(opened).toMatchObject({ ok: true, saved: '2026-03-01T00:00:00.000Z', handIns, refused: [] });
    const before = buildGradebook(gradeClassSync(sheet, handIns));
    expect(buildGradebook(gradeClassSync(opened.sheet, opened.handIns))).toEqual(before);
    const doc = JSON.parse(text);
    const hostile = JSON.parse(`{"kind":"fresnel-lab-class","version":1,"sheet":${JSON.stringify(sheet)},"__proto__":{"polluted":1},"grades":[5],"handIns":[{"source":"a","data":{}},{"source":"","data":{}},{"__proto__":{"source":"x","data":{}}},7,{"source":"b"}]}`);
    const read = readClassFile(JSON.stringify(hostile));
    expect(read.ok && read.handIns).toEqual([{ source: 'a', data: {} }]);
    expect(read.ok && read.refused.map((r) => r.source)).toEqual(['class view', 'class view', 'hand-in 2 of the class view', 'hand-in 3 of the class view', 'hand-in 4 of the class view', 'hand-in 5 of the class view']);
    expect({}.polluted).toBeUndefined();
    expect(readClassFile(JSON.stringify({ ...doc, kind: 'something' })).ok).toBe(false);
    expect(readClassFile(JSON.stringify({ ...doc, version: 2 }))).toEqual({ ok: false, problems: [expect.stringMatching(/version must be 1/)] });
    expect(readClassFile('{"kind":"fresnel-lab-class"')).toEqual({ ok: false, problems: [expect.stringMatching(/not readable JSON/)] });
    expect(readClassFile(text, { maxClassFileBytes: 100 }).ok).toBe(false);
    expect(readClassFile(/** @type {any} */ (42)).ok).toBe(false);
    const capped = readClassFile(text, { maxHandIns: 1 });
    expect(capped.ok && [capped.handIns.length, capped.refused[0].source]).toEqual([1, 'hand-ins 2–2 of the class view']);
  });
});

describe('a whole class view', () => {
  it('from a synthetic class as an LMS zip, as files and as codes: the same gradebook; saved and opened with more codes added', async () => {
    const synthetic = syntheticClass({ students: 12, questions: 10, seed: 'test' });
    const fromZip = await buildClassView({ sheet: synthetic.sheet, files: [{ name: 'class.zip', bytes: synthetic.zip }] });
    const fromFiles = await buildClassView({ sheet: synthetic.sheet, files: synthetic.files });
    const fromCodes = await buildClassView({ sheet: synthetic.sheet, text: synthetic.codes });
    for (const view of [fromZip, fromFiles, fromCodes]) {
      expect(view.ok && [view.graded.length, view.refused]).toEqual([12, []]);
    }
    const scores = (view) => view.gradebook.rows.map((r) => [r.name, r.score, r.marks.join()]);
    expect(scores(fromFiles)).toEqual(scores(fromZip));
    expect(scores(fromCodes)).toEqual(scores(fromZip));
    expect(fromZip.summary).toHaveLength(10);
    const saved = writeClassFile({ sheet: fromZip.sheet, handIns: fromZip.handIns.slice(0, 10) });
    const phases = new Set();
    const reopened = await buildClassView({ classFile: saved, text: synthetic.codes.split('\n').slice(10).join('\n') }, { onProgress: (p) => phases.add(p.phase) });
    expect(reopened.ok && scores(reopened)).toEqual(scores(fromZip));
    expect(phases).toContain('reading');
    expect(phases).toContain('summarising');
    expect(await buildClassView({ files: synthetic.files })).toEqual({ ok: false, problems: [expect.stringMatching(/Give the sheet you set/)] });
    // A saved view's hand-ins count against the cap on hand-ins read in all.
    const capped = await buildClassView({ classFile: saved, text: synthetic.codes }, { caps: { maxHandIns: 11 } });
    expect(capped.ok && [capped.graded.length, capped.refused.length]).toEqual([11, 11]);
    const full = await buildClassView({ classFile: saved, text: synthetic.codes }, { caps: { maxHandIns: 10 } });
    expect(full.ok && full.refused).toEqual([{ source: 'files and text', reason: expect.stringMatching(/holds as many hand-ins/) }]);
  });

  it('the worker answers a request with progress, then a view that survives structured cloning; an error is posted, not thrown', async () => {
    const synthetic = syntheticClass({ students: 4, questions: 6, seed: 'worker' });
    const posted = [];
    let listener;
    serveClassView({ addEventListener: (_type, fn) => { listener = fn; }, postMessage: (m) => posted.push(structuredClone(m)) });
    await listener({ data: { id: 7, request: { sheet: synthetic.sheet, files: [{ name: 'class.zip', bytes: synthetic.zip }] } } });
    expect(posted[0]).toEqual({ id: 7, progress: { phase: 'reading' } });
    const { view } = posted[posted.length - 1];
    expect([view.ok, view.gradebook.rows.length, view.summary.length]).toEqual([true, 4, 6]);
    await listener({ data: { id: 8, request: { sheet: synthetic.sheet, classFile: 5 } } });
    expect(posted[posted.length - 1]).toEqual({ id: 8, view: { ok: false, problems: [expect.stringMatching(/file of text/)] } });
    await listener({ data: null });
    expect(posted[posted.length - 1]).toMatchObject({ view: { ok: false } });
  });

  it('the worker writes its words in the language the page asks for, and English for one the lab does not speak', async () => {
    const synthetic = syntheticClass({ students: 3, questions: 4, seed: 'words' });
    const posted = [];
    let listener;
    serveClassView({ addEventListener: (_type, fn) => { listener = fn; }, postMessage: (m) => posted.push(structuredClone(m)) });
    const request = { sheet: synthetic.sheet, files: [{ name: 'class.zip', bytes: synthetic.zip }, { name: 'photo.png', bytes: new Uint8Array(4) }] };
    const last = () => posted[posted.length - 1];
    try {
      // The pseudo-locale (?lang=en-XA on the page): every word the worker writes is a message, accented and bracketed ⟦…⟧.
      await listener({ data: { id: 1, request, lang: 'en-XA' } });
      const { view } = last();
      expect(view.refused).toEqual([{ source: 'photo.png', reason: expect.stringMatching(/^⟦ñót réád: á \.pñg fílé ís ñó háñd-íñ .*⟧$/) }]);
      const options = view.summary.flatMap((s) => s.options ?? []);
      expect(options.length).toBeGreaterThan(0);
      expect(options.every((o) => /^⟦.*⟧$/.test(o.text))).toBe(true);
      const explanations = view.graded.flatMap((g) => g.result.results.map((r) => r.explanation));
      expect(explanations.length).toBeGreaterThan(0);
      expect(explanations.every((text) => /^⟦.*⟧$/.test(text))).toBe(true);
      await listener({ data: { id: 2, request, lang: 'xx' } });
      expect(last().view.refused[0].reason).toMatch(/^not read: a \.png file is no hand-in/);
    } finally {
      await listener({ data: { id: 3, request: null, lang: 'en' } }); // modules are shared between test files
    }
    expect(last().view.ok).toBe(false);
  });
});
