// An LMS's "download all submissions" as it comes (src/homework/class/): Moodle's with file and
// online-text hand-ins, in folders or flat; Canvas's with late and resubmitted files and online
// text; files without an extension read for what they hold; every student named and given their
// id in that LMS from the path.
import { describe, expect, it } from 'vitest';
import { strToU8, zipSync } from 'fflate';
import { readClassHandIns } from '../../src/homework/class/readClassHandIns.js';
import { gradeClassSync } from '../../src/homework/class/gradeClass.js';
import { buildGradebook } from '../../src/homework/class/buildGradebook.js';
import { lmsUser } from '../../src/homework/class/lmsName.js';
import { moodleWorksheet } from '../../src/homework/class/lmsGrades.js';
import { htmlToText } from '../../src/homework/class/htmlText.js';
import { handInToCode, makeHandIn } from '../../src/homework/sheetCodes.js';

const sheet = { version: 1, title: 'Week 3', items: [{ question: 'exact-r' }, { question: 'metal-grazing' }] };
const handIn = (name, seed, time = '2026-01-10T10:00:00.000Z') => makeHandIn({ sheet, seed, name, answers: ['0.05', 'towards-white'], time });
const json = (data) => strToU8(JSON.stringify(data));
/** Moodle's online text as its download writes it (assignsubmission_onlinetext: the editor's HTML in a page). */
const onlineText = (body) => strToU8(`<!DOCTYPE html><html><head><meta charset="UTF-8"></head><body>${body}</body></html>`);
const graded = (files, text = '') => {
  const read = readClassHandIns({ files, text });
  const grades = gradeClassSync(sheet, read.handIns);
  if (!grades.ok) throw new Error(grades.problems.join(' '));
  return { read, book: buildGradebook(grades) };
};
const who = (book) => book.rows.map((r) => [r.name || r.lmsName, r.lms, r.lmsId, r.counted]);

describe('a Moodle download', () => {
  it('reads file and online-text hand-ins, in folders and flat, and a file without an extension; every student named', () => {
    const code = handInToCode(handIn('', 'moodle-2'));
    const wrapped = handInToCode(handIn('Zoë Müller', 'moodle-4')).match(/.{1,70}/g).join('<br>\n');
    const zip = zipSync({
      'Ada Lovelace_100001_assignsubmission_file_': { 'handin.json': json(handIn('Ada Lovelace', 'moodle-1')) },
      'Seán O Brien_100002_assignsubmission_onlinetext_': {
        'onlinetext.html': onlineText(`<p>Here is my code &amp; thanks:</p><p>${code}</p>`),
      },
      '李伟_100003_assignsubmission_file_': { handin: json(handIn('李伟', 'moodle-3')), scan: strToU8('%PDF-1.7 …') },
      'Zoë Müller_100004_assignsubmission_onlinetext_onlinetext.html': onlineText(`<div>${wrapped}</div>`),
    });
    const { read, book } = graded([{ name: 'Week 3-123.zip', bytes: zip }]);
    expect(read.refused).toEqual([{ source: 'Week 3-123.zip/李伟_100003_assignsubmission_file_/scan', reason: expect.stringMatching(/a PDF/) }]);
    expect(who(book).sort()).toEqual([
      ['Ada Lovelace', 'moodle', '100001', true], ['Seán O Brien', 'moodle', '100002', true],
      ['Zoë Müller', 'moodle', '100004', true], ['李伟', 'moodle', '100003', true],
    ]);
    expect(book.rows.find((r) => r.lmsId === '100002').flags.map((f) => f.text)).toEqual([expect.stringMatching(/says Seán O Brien/)]);
  });

  it('the participant number tells apart hand-ins with no name, even under blind marking (every folder says "Participant")', () => {
    const zip = zipSync({
      'Participant_200001_assignsubmission_file_': { 'h.json': json(handIn('', 'p1')) },
      'Participant_200002_assignsubmission_file_': { 'h.json': json(handIn('', 'p2')) },
    });
    const { book } = graded([{ name: 'blind.zip', bytes: zip }]);
    expect(book.rows.map((r) => [r.lmsId, r.counted])).toEqual([['200001', true], ['200002', true]]);
  });
});

describe('two students of one name', () => {
  it('are two students when their participant numbers differ; a pasted hand-in joins the one student of its name, never one of two', () => {
    const zip = zipSync({
      'Li Wei_100003_assignsubmission_file_': { handin: json(handIn('Li Wei', 'lw3', '2026-01-10T10:00:00.000Z')) },
      'Li Wei_100004_assignsubmission_file_': { 'handin.json': json(handIn('Li Wei', 'lw4', '2026-01-11T10:00:00.000Z')) },
      'Ada Lovelace_100001_assignsubmission_file_': { 'h.json': json(handIn('Ada Lovelace', 'a1', '2026-01-09T10:00:00.000Z')) },
      // One seed under two participants of one name: one handed in the other's sheet.
      'Bo Berg_100005_assignsubmission_file_': { 'h.json': json(handIn('Bo Berg', 'bo', '2026-01-09T10:00:00.000Z')) },
      'Bo Berg_100006_assignsubmission_file_': { 'h.json': json(handIn('Bo Berg', 'bo', '2026-01-09T11:00:00.000Z')) },
    });
    // Later, by mail (no path, so no participant number): Ada again, and a Li Wei on 100003's seed.
    const mail = [handIn('ada lovelace', 'a1', '2026-01-12T10:00:00.000Z'), handIn('Li Wei', 'lw3', '2026-01-12T10:00:00.000Z')];
    const { book } = graded([{ name: 'Week 3-123.zip', bytes: zip }], mail.map(handInToCode).join('\n'));
    const rows = book.rows.map((r) => [r.name, r.lmsId, r.counted, r.flags.map((f) => f.kind).filter((k) => k !== 'no-name')]);
    expect(rows).toEqual([
      ['Li Wei', '100003', true, ['shared-seed']],
      ['Li Wei', '100004', true, []],
      ['Ada Lovelace', '100001', false, ['superseded']],
      ['Bo Berg', '100005', true, ['shared-seed']],
      ['Bo Berg', '100006', true, ['shared-seed']],
      ['ada lovelace', '', true, ['resubmitted']],
      ['Li Wei', '', true, ['shared-seed']], // could be either Li Wei's: counted on its own, its seed flagged
    ]);
    expect([book.students, book.superseded]).toEqual([6, 1]);
    const sheetFile = moodleWorksheet(book, { now: new Date('2026-02-01T12:00:00Z') });
    expect(sheetFile.cells.slice(1).map((c) => c[0]).sort()).toEqual(
      ['Participant 100001', 'Participant 100003', 'Participant 100004', 'Participant 100005', 'Participant 100006']);
    expect(sheetFile.left.map((l) => [l.row.name, l.why])).toEqual([['Li Wei', 'no-id']]);
  });
});

describe('a Canvas download', () => {
  it('names students from late, resubmitted and online-text files, and keeps the user id', () => {
    const { read, book } = graded([{ name: 'course-week-3 submissions.zip', bytes: zipSync({
      'lovelaceada_12345_900001_handin.json': json(handIn('Ada Lovelace', 'c1', '2026-01-10T10:00:00.000Z')),
      'lovelaceada_LATE_12345_900002_handin-1.json': json(handIn('Ada Lovelace', 'c1', '2026-01-12T10:00:00.000Z')),
      'obrienseán_LATE_23456_900003_handin.json': json(handIn('', 'c2')),
      '李伟_34567_text.html': strToU8(`<p>${handInToCode(handIn('', 'c3'))}</p>`),
    }) }]);
    expect(read.refused).toEqual([]);
    expect(who(book)).toEqual([
      ['Ada Lovelace', 'canvas', '12345', false], ['Ada Lovelace', 'canvas', '12345', true],
      ['obrienseán', 'canvas', '23456', true], ['李伟', 'canvas', '34567', true],
    ]);
  });

  it('reads the published file name forms, and finds no student in a plain name', () => {
    expect(lmsUser('x.zip/lovelaceada_LATE_12345_67890_handin.json')).toEqual({ lms: 'canvas', name: 'lovelaceada', id: '12345' });
    expect(lmsUser('lovelaceada_late_12345_67890_handin.json')).toEqual({ lms: 'canvas', name: 'lovelaceada', id: '12345' });
    expect(lmsUser('smith2john_99_1_h.json')).toEqual({ lms: 'canvas', name: 'smith2john', id: '99' });
    expect(lmsUser('obrienseán_23456_text.html, line 3')).toEqual({ lms: 'canvas', name: 'obrienseán', id: '23456' });
    // A source written in another language says the line in its own words: the online text is still found.
    for (const line of [', línea 3', ' (Zeile 3)', '⟦, líñé 3 ··⟧']) {
      expect(lmsUser(`obrienseán_23456_text.html${line}`), line).toEqual({ lms: 'canvas', name: 'obrienseán', id: '23456' });
    }
    expect(lmsUser('obrienseán_23456_text.htmlx')).toEqual({ lms: '', name: '', id: '' });
    expect(lmsUser('Ada Lovelace_123456_assignsubmission_file_handin.json')).toEqual({ lms: 'moodle', name: 'Ada Lovelace', id: '123456' });
    expect(lmsUser('g.zip/Homework 3_alovelace_attempt_2026-01-02-10-00-00_h.json')).toEqual({ lms: 'blackboard', name: 'alovelace', id: '' });
    for (const plain of ['handin.json', 'anon_x1y2z_67890_handin.json', 'week_three.json']) expect(lmsUser(plain)).toEqual({ lms: '', name: '', id: '' });
  });
});

describe('HTML and files without an extension', () => {
  it('an HTML page gives its text: tags dropped, entities decoded, blocks on lines; scripts, styles, comments and attributes left out', () => {
    const html = '<html><head><title>T</title><style>p{}</style><script>FLH1.x</script></head>'
      + '<body><p title="FLH1.y">a &amp; b&nbsp;&lt;c&gt;</p><!-- FLH1.z --><ul><li>one</li><li>two</li></ul>x<br>y</body></html>';
    expect(htmlToText(html).replace(/\n+/g, '\n')).toBe('\nT\na & b\u00a0<c>\none\ntwo\nx\ny\n');
  });

  it('a file without an extension is read for what it holds: JSON, codes, a zip; binary and empty ones refused by name', () => {
    const code = handInToCode(handIn('Bo', 'b'));
    const read = readClassHandIns({ files: [
      { name: 'handin', bytes: json(handIn('Ada', 'a')) },
      { name: 'codes', bytes: strToU8(`Mine: ${code}\n`) },
      { name: 'page', bytes: strToU8(`<!doctype html><p>${handInToCode(handIn('Cy', 'c'))}</p>`) },
      { name: 'bundle', bytes: zipSync({ 'd.json': json(handIn('Di', 'd')) }) },
      { name: 'photo', bytes: new Uint8Array([0xff, 0xd8, 0xff, 0xe0, 0, 16, 74, 70]) },
      { name: 'blank', bytes: new Uint8Array(0) },
    ] });
    expect(read.handIns.map((h) => [h.source, h.data.name])).toEqual([
      ['handin', 'Ada'], ['codes, line 1', 'Bo'], ['page, line 2', 'Cy'], ['bundle/d.json', 'Di'],
    ]);
    expect(read.refused).toEqual([
      { source: 'photo', reason: expect.stringMatching(/binary file/) }, { source: 'blank', reason: 'an empty file.' },
    ]);
  });
});
