// Properties of what is read from an LMS's download (src/homework/class/): the HTML text reader
// never throws, gives text without markup back unchanged and escaped text back as it was; a code
// inside any HTML (wrapped over <br>s, among tags and entities) is read, as it is from a file
// without an extension; the student's name and id come back from every path an LMS writes, and
// no path makes the readers throw; a participant number is one student, whatever names are given.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { strToU8 } from 'fflate';
import { htmlToText, looksLikeHtml } from '../../src/homework/class/htmlText.js';
import { contentKind, fileKind } from '../../src/homework/class/fileKind.js';
import { lmsUser } from '../../src/homework/class/lmsName.js';
import { readClassHandIns } from '../../src/homework/class/readClassHandIns.js';
import { gradeClassSync } from '../../src/homework/class/gradeClass.js';
import { buildGradebook } from '../../src/homework/class/buildGradebook.js';
import { moodleWorksheet } from '../../src/homework/class/lmsGrades.js';
import { handInToCode, makeHandIn } from '../../src/homework/sheetCodes.js';
import { anyText } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

const sheet = { version: 1, title: 'Week 3', items: [{ question: 'exact-r' }, { question: 'metal-grazing' }] };
const handIn = (k) => makeHandIn({ sheet, seed: `s${k}`, name: `Student ${k}`, answers: ['0.05', 'dark'], time: '2026-01-01T00:00:00.000Z' });
/** HTML's own escaping of text (the HTML standard's "escaping a string" in text content). */
const escapeHtml = (text) => text.replaceAll('&', '&amp;').replaceAll('<', '&lt;').replaceAll('>', '&gt;');
const PIECES = ['<', '>', '</', '/>', '<p>', '</p>', '<br>', '<script>', '</script>', '<style>', '<!--', '-->', '<![CDATA[', ']]>', '&',
  '&amp;', '&#', '&#x', '&#0;', '&#x110000;', ';', '"', "'", '=', 'a', ' ', '\n', '<textarea>', '<plaintext>', '<svg><![CDATA[x', 'FLH1.'];
const tagSoup = fc.array(fc.constantFrom(...PIECES), { maxLength: 60 }).map((p) => p.join(''));
/** Markup that holds no code and does not hide what follows it (no unclosed comment, script or raw-text element). */
const harmless = fc.array(fc.constantFrom('<p>', '</p>', '<div class="x">', '</div>', '<b>', '</b>', '&amp;', '&nbsp;', '&eacute;', 'Hi,',
  ' ', '\n', '<span style="color: red">', '</span>', '<!-- a note -->', '<br/>', 'Thanks!'), { maxLength: 12 }).map((p) => p.join(''));

describe('the HTML text reader', () => {
  it('never throws on any text or tag soup, and gives text without markup back as it is', () => {
    check(fc.property(fc.oneof(anyText, tagSoup, fc.string({ unit: 'binary', maxLength: 400 })), (html) => {
      const text = htmlToText(html);
      expect(typeof text).toBe('string');
      if (!/[<&]/.test(html)) expect(text).toBe(html);
    }), 300);
  });

  it('escaped text in a paragraph comes back exactly, whatever it holds', () => {
    check(fc.property(fc.oneof(anyText, fc.string({ unit: 'grapheme', maxLength: 60 }), tagSoup), (text) => {
      expect(htmlToText(`<p>${escapeHtml(text)}</p>`)).toBe(`\n${text}\n`);
    }), 300);
  });

  it('a code inside any markup, wrapped over lines with <br> or not, is read from an .html file and from one without an extension', () => {
    check(fc.property(fc.nat(40), harmless, harmless, fc.integer({ min: 0, max: 120 }), fc.boolean(), (k, before, after, wrap, doc) => {
      const code = handInToCode(handIn(k));
      const body = wrap < 16 ? code : code.match(new RegExp(`.{1,${wrap}}`, 'g')).join('<br>\n');
      const html = `${doc ? '<!DOCTYPE html><html><body>' : ''}<p>${before}</p><p>${body}</p><div>${after}</div>`;
      for (const name of ['onlinetext.html', 'x/lovelaceada_12_text.HTM', ...(doc ? ['handin'] : [])]) {
        const read = readClassHandIns({ files: [{ name, bytes: strToU8(html) }] });
        expect(read.handIns.map((h) => h.data), name).toEqual([handIn(k)]);
        expect(read.refused, name).toEqual([]);
      }
    }), 150);
  });

  it('says a text is a page only when it starts like one', () => {
    check(fc.property(anyText, (text) => {
      if (looksLikeHtml(text)) expect(text.trimStart().startsWith('<')).toBe(true);
    }));
  });
});

describe('files without an extension', () => {
  it('any bytes are read as a zip, as text, or refused with a reason; never thrown', () => {
    check(fc.property(fc.uint8Array({ maxLength: 2000 }), (bytes) => {
      const kind = contentKind(bytes);
      expect(kind.kind === 'zip' || kind.kind === 'text' || (typeof kind.reason === 'string' && kind.reason.length > 0)).toBe(true);
      const read = readClassHandIns({ files: [{ name: 'handin', bytes }] });
      expect(read.handIns.length + read.refused.length).toBeGreaterThan(0);
    }), 300);
  });

  it('any name is read by its extension, by its content, or refused with a reason', () => {
    check(fc.property(anyText, (name) => {
      const kind = fileKind(name);
      expect(['json', 'text', 'html', 'zip', 'by-content'].includes(kind.kind) || kind.reason.length > 0).toBe(true);
    }));
  });
});

describe('the student an LMS names', () => {
  // Moodle drops "_" from names (it makes them spaces) and "/" cannot be in a folder's name.
  const moodleName = fc.string({ unit: 'grapheme', minLength: 1, maxLength: 20 }).filter((s) => !/[_/]/.test(s) && s.trim() !== '');
  // Canvas keeps letters, digits and "_" of the sortable name (sanitize_file_name), and collapses "_123_".
  const canvasName = fc.stringMatching(/^[\p{L}\p{N}]{1,12}(?:_[\p{L}]{1,5})?$/u);
  const id = fc.stringMatching(/^[1-9]\d{0,9}$/);
  const fileName = fc.string({ maxLength: 30 }).filter((s) => !s.includes('/')).map((s) => `${s}.json`);

  it('a Moodle path gives the name and participant number, in a folder or flat, file or online text', () => {
    check(fc.property(moodleName, id, fc.constantFrom('file', 'onlinetext'), fc.boolean(), fileName, (name, n, plugin, folder, file) => {
      const prefix = `${name}_${n}_assignsubmission_${plugin}_`;
      const path = folder ? `Week 3-9.zip/${prefix}/${file}` : `${prefix}${file}`;
      expect(lmsUser(path)).toEqual({ lms: 'moodle', name: name.trim(), id: n });
    }));
  });

  it('a Canvas file name gives the name and user id, late or not, a file or online text', () => {
    check(fc.property(canvasName, fc.boolean(), id, fc.oneof(id.map((a) => `_${a}_h.json`), fc.constant('_text.html')), (name, late, n, tail) => {
      expect(lmsUser(`subs.zip/${name}${late ? '_LATE' : ''}_${n}${tail}, line 2`)).toEqual({ lms: 'canvas', name, id: n });
    }));
  });

  it('never throws on any path; an id is digits or nothing', () => {
    check(fc.property(fc.array(anyText, { maxLength: 4 }).map((parts) => parts.join('/')), (path) => {
      const user = lmsUser(path);
      expect(user.id).toMatch(/^\d*$/);
      if (user.lms === '') expect(user).toEqual({ lms: '', name: '', id: '' });
      else expect(['moodle', 'canvas', 'blackboard']).toContain(user.lms);
    }));
  });
});

describe('the students of a Moodle download', () => {
  // Names from a small pool, so that students share them, as 李伟 or Li Wei do in a real class.
  const NAMES = ['Li Wei', 'li  wei', '李伟', 'Ada', ''];
  const entry = fc.record({ id: fc.integer({ min: 1, max: 5 }), name: fc.constantFrom(...NAMES), seed: fc.constantFrom('a', 'b', 'c'),
    day: fc.integer({ min: 1, max: 9 }) });

  it('each participant number is one student, counted once at its latest hand-in, and goes into the worksheet once', () => {
    check(fc.property(fc.array(entry, { minLength: 1, maxLength: 8 }), (entries) => {
      const handIns = entries.map(({ id, name, seed, day }) => ({
        source: `w.zip/${NAMES[id % 4]}_${100000 + id}_assignsubmission_file_/h.json`,
        data: makeHandIn({ sheet, seed, name, answers: ['0.05', 'dark'], time: `2026-01-0${day}T00:00:00.000Z` }),
      }));
      const grades = gradeClassSync(sheet, handIns);
      if (!grades.ok) throw new Error(grades.problems.join(' '));
      const book = buildGradebook(grades);
      const ids = [...new Set(entries.map((e) => String(100000 + e.id)))].sort();
      expect(book.students).toBe(ids.length);
      for (const id of ids) {
        const own = book.rows.filter((r) => r.lmsId === id);
        const latest = own.reduce((a, b) => (Date.parse(b.time) >= Date.parse(a.time) ? b : a));
        expect(own.filter((r) => r.counted)).toEqual([latest]);
      }
      expect(moodleWorksheet(book).students.map((s) => s.id).sort()).toEqual(ids);
    }), 100);
  });
});
