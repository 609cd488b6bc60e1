// Properties of the class view (src/homework/class/): reading never throws on any bytes or text and
// accounts for every input (graded or refused, the counts add up), the CSV reads back as its cells
// through a plain RFC 4180 parser and never starts a cell with a formula, and a class view saved and
// opened again grades to the same gradebook.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { strToU8, zipSync } from 'fflate';
import { readClassHandIns } from '../../src/homework/class/readClassHandIns.js';
import { gradeClassSync } from '../../src/homework/class/gradeClass.js';
import { buildGradebook } from '../../src/homework/class/buildGradebook.js';
import { summarizeQuestions } from '../../src/homework/class/summarizeQuestions.js';
import { cellsToCsv, gradebookToCsv, textCell } from '../../src/homework/class/gradebookToCsv.js';
import { readClassFile, writeClassFile } from '../../src/homework/class/classFile.js';
import { syntheticClass } from '../../src/homework/class/syntheticClass.js';
import { handInToCode, makeHandIn } from '../../src/homework/sheetCodes.js';
import { anyJson, anyText, ownObject } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

const sheet = { version: 1, title: 'Fresnel', items: [{ question: 'exact-r' }, { question: 'metal-grazing' }, { question: 'critical-predict' }] };
const handIn = (k) => makeHandIn({ sheet, seed: `s${k}`, name: `Student ${k}`, answers: ['0.1', 'dark', 40], time: '2026-01-01T00:00:00.000Z' });
const FORMULA = /^[=+\-@\t\r\uff1d\uff0b\uff0d\uff20]/;

/** RFC 4180, plainly: records end in CRLF, a quoted field may hold anything with its quotes doubled. */
function parseCsv(text, separator = ',') {
  expect(text.startsWith('\ufeff')).toBe(true);
  const records = [];
  let record = [];
  let field = '';
  let i = 1;
  while (i < text.length) {
    if (text[i] === '"') {
      for (i += 1; ; i += 1) {
        if (text[i] === '"' && text[i + 1] === '"') field += '"', i += 1;
        else if (text[i] === '"') break;
        else field += text[i];
      }
      i += 1;
    }
    if (text.startsWith('\r\n', i)) {
      record.push(field);
      records.push(record);
      record = [];
      field = '';
      i += 2;
    } else if (text[i] === separator) {
      record.push(field);
      field = '';
      i += 1;
    } else {
      field += text[i];
      i += 1;
    }
  }
  expect(field === '' && record.length === 0).toBe(true); // the last record ends in CRLF
  return records;
}

/** Every input named by at least one outcome (a hand-in or a refusal whose source starts with its name). */
function accounted(read, names) {
  const sources = [...read.handIns, ...read.refused].map((x) => x.source);
  for (const name of names) expect(sources.some((s) => s.startsWith(name)), name).toBe(true);
  for (const r of read.refused) expect(typeof r.reason === 'string' && r.reason.length > 0).toBe(true);
}

const validZip = zipSync({
  'Ada_1_assignsubmission_file_': { 'h.json': strToU8(JSON.stringify(handIn(1))), 'c.txt': strToU8(handInToCode(handIn(2))) },
  'inner.zip': zipSync({ 'x.json': strToU8(JSON.stringify(handIn(3))) }, { level: 0 }),
  'notes.pdf': strToU8('%PDF'),
});

describe('reading a class', () => {
  it('never throws on any bytes under any name, and names every file in what it returns', () => {
    const name = fc.constantFrom('a.zip', 'b.json', 'c.txt', 'd.bin', 'e', '__MACOSX/._f.json', 'G.ZIP');
    check(fc.property(fc.array(fc.record({ name, bytes: fc.uint8Array({ maxLength: 3000 }) }), { maxLength: 4 }), (files) => {
      const unique = files.map((f, i) => ({ ...f, name: `${i}/${f.name}` }));
      accounted(readClassHandIns({ files: unique }), unique.map((f) => f.name));
    }));
  });

  it('never throws on a zip with bytes changed or cut, and names what it cannot read', () => {
    const edit = fc.record({ at: fc.nat(validZip.length - 1), to: fc.nat(255) });
    check(fc.property(fc.array(edit, { minLength: 1, maxLength: 8 }), fc.nat(validZip.length), (edits, cut) => {
      const bytes = validZip.slice(0, Math.max(cut, validZip.length - 200));
      for (const { at, to } of edits) if (at < bytes.length) bytes[at] = to;
      const read = readClassHandIns({ files: [{ name: 'class.zip', bytes }] });
      accounted(read, ['class.zip']);
      expect(read.handIns.length).toBeLessThanOrEqual(3);
    }), 300);
  });

  it('never throws on any text, and refuses a text that is not empty with a reason when it finds nothing', () => {
    const text = fc.oneof(anyText, fc.string({ unit: 'binary', maxLength: 300 }),
      fc.array(fc.constantFrom('FLH1.', 'eyJ', '{', '}', '"fresnel-lab-hand-in"', '""', '\n', '> ', '=\n', 'x', '"', '\\'), { maxLength: 40 }).map((p) => p.join('')));
    check(fc.property(text, (t) => {
      const read = readClassHandIns({ text: t });
      if (t.trim()) accounted(read, ['pasted text']);
      else expect(read).toEqual({ handIns: [], refused: [] });
    }), 300);
  });

  it('every code is graded or refused: valid codes (wrapped or not) are read, cut ones refused, the counts add up', () => {
    const junk = fc.string({ maxLength: 40 }).filter((s) => !s.includes('FLH1.') && !s.includes('fresnel-lab-hand-in'));
    const entry = fc.oneof(
      fc.record({ kind: fc.constant('valid'), k: fc.nat(50), wrap: fc.integer({ min: 0, max: 90 }), quote: fc.boolean() }),
      fc.record({ kind: fc.constant('cut'), k: fc.nat(50), keep: fc.double({ min: 0, max: 0.97, noNaN: true }) }),
      fc.record({ kind: fc.constant('junk'), text: junk }),
    );
    check(fc.property(fc.array(entry, { maxLength: 12 }), (entries) => {
      const lines = entries.map((e) => {
        if (e.kind === 'junk') return e.text;
        const code = handInToCode(handIn(e.k));
        if (e.kind === 'cut') return code.slice(0, 5 + Math.floor(e.keep * (code.length - 5)));
        return e.wrap < 20 ? code : code.match(new RegExp(`.{1,${e.wrap}}`, 'g')).join(e.quote ? '\n> ' : '\n');
      });
      const read = readClassHandIns({ text: lines.join('\n') });
      const valid = entries.filter((e) => e.kind === 'valid');
      const cut = entries.filter((e) => e.kind === 'cut').length;
      expect(read.handIns.map((h) => h.data)).toEqual(valid.map((e) => handIn(e.k)));
      if (valid.length || cut) expect(read.refused).toHaveLength(cut);
      const grades = gradeClassSync(sheet, read.handIns);
      expect(grades.ok && grades.graded.length + grades.refused.length).toBe(read.handIns.length);
    }), 200);
  });
});

describe('grading a class', () => {
  it('any data, or a hand-in with a field replaced by anything, is graded or refused; the gradebook, summary and CSV follow', () => {
    const field = fc.constantFrom('kind', 'version', 'sheet', 'seed', 'name', 'answers', 'attempts', 'time', '__proto__', 'constructor');
    const data = fc.oneof(anyJson,
      fc.tuple(fc.nat(5), field, anyJson).map(([k, key, value]) => ownObject([...Object.entries(handIn(k)).filter(([f]) => f !== key), [key, value]])),
      fc.nat(5).map(handIn));
    check(fc.property(fc.array(fc.record({ source: anyText, data }), { maxLength: 6 }), (handIns) => {
      const grades = gradeClassSync(sheet, handIns);
      expect(grades.ok).toBe(true);
      if (!grades.ok) return;
      expect(grades.graded.length + grades.refused.length).toBe(handIns.length);
      const book = buildGradebook(grades);
      expect(book.rows).toHaveLength(grades.graded.length);
      for (const summary of summarizeQuestions(grades, book)) expect(summary.right + summary.wrong + summary.unanswered).toBe(book.students);
      expect(parseCsv(gradebookToCsv(book))).toHaveLength(1 + book.students);
      const semicolons = parseCsv(gradebookToCsv(book, { semicolons: true }), ';');
      expect(semicolons).toHaveLength(1 + book.students);
      for (const record of semicolons) expect(record).toHaveLength(semicolons[0].length);
    }), 200);
  });
});

describe('CSV', () => {
  it('reads back as its cells through an RFC 4180 parser, whatever they hold', () => {
    const cell = fc.oneof(fc.string({ unit: 'grapheme', maxLength: 12 }), fc.constantFrom('"', '""', ',', ';', '\r\n', '\n', '\r', ' ', '=1',
      'a"b,c\r\nd', '1;2'));
    check(fc.property(fc.array(fc.array(cell, { minLength: 1, maxLength: 5 }), { maxLength: 5 }), (cells) => {
      expect(parseCsv(cellsToCsv(cells))).toEqual(cells);
      expect(parseCsv(cellsToCsv(cells, { separator: ';' }), ';')).toEqual(cells);
    }), 300);
  });

  it('a name, a source or a seed never starts a formula in the file', () => {
    check(fc.property(anyText, fc.string({ unit: 'grapheme', maxLength: 8 }), (text, prefix) => {
      for (const t of [text, `${prefix}${text}`, `=${text}`, `-${text}`]) {
        expect(textCell(t)).not.toMatch(FORMULA);
        expect(textCell(t)).toBe(FORMULA.test(t) ? `'${t}` : t);
      }
    }));
  });
});

describe('a class view saved and opened', () => {
  it('opens to the same gradebook and summary, graded again', () => {
    check(fc.property(fc.integer({ min: 1, max: 6 }), fc.string({ maxLength: 6 }), fc.boolean(), fc.nat(3), (students, seed, classSeed, repeat) => {
      const made = syntheticClass({ students, questions: 5, seed: `p${seed}`, ...(classSeed ? { classSeed: 'class' } : {}) });
      const handIns = [...made.handIns, ...made.handIns.slice(0, repeat)]; // a student handing in again
      const grades = gradeClassSync(made.sheet, handIns);
      const opened = readClassFile(writeClassFile({ sheet: made.sheet, handIns }));
      expect(opened.ok).toBe(true);
      if (!opened.ok) return;
      const again = gradeClassSync(JSON.parse(JSON.stringify(opened.sheet)), opened.handIns);
      expect(grades.ok && again.ok).toBe(true);
      const book = buildGradebook(grades);
      expect(buildGradebook(again)).toEqual(book);
      expect(summarizeQuestions(again, buildGradebook(again))).toEqual(summarizeQuestions(grades, book));
    }), 25);
  });
});
