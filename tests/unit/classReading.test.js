// Reading a class's hand-ins (src/homework/class/): an LMS's zip with folders and zips inside, zip
// bombs refused by name before or while unpacking, codes in mail, CSV and LMS text, and every file
// that is not read named with its reason. What a hostile input costs is counted in steps (bytes
// given to the inflater and bytes it writes; characters read), never timed: such a test fails when
// a bound is lost, and never because the machine is slow.
import { describe, expect, it, vi } from 'vitest';
import { strToU8, zipSync } from 'fflate';

// fflate as it is, counting what unzipBounded.js asks of it: compressed bytes handed to an inflater
// (inflateSync's input, Inflate's pushes) and bytes it writes out (inflateSync's result, Inflate's chunks).
const inflated = vi.hoisted(() => ({ given: 0, written: 0 }));
vi.mock('fflate', async (importOriginal) => {
  const fflate = await importOriginal();
  class Inflate extends fflate.Inflate {
    constructor(...args) {
      super(...args);
      const ondata = this.ondata;
      this.ondata = (chunk, final) => {
        inflated.written += chunk.length;
        ondata(chunk, final);
      };
    }

    push(chunk, final) {
      inflated.given += chunk.length;
      super.push(chunk, final);
    }
  }
  const inflateSync = (data, options) => {
    inflated.given += data.length;
    const out = fflate.inflateSync(data, options);
    inflated.written += out.length;
    return out;
  };
  return { ...fflate, Inflate, inflateSync };
});

// The codes' decoder as it is, counting the characters it is given (findHandIns decodes a code's
// pieces) while countingReads counts.
const decoding = vi.hoisted(() => ({ count: null, given: 0 }));
vi.mock('../../src/homework/sheetCodes.js', async (importOriginal) => {
  const codes = await importOriginal();
  const handInFromText = (text) => {
    decoding.given += typeof text === 'string' ? text.length : 0;
    decoding.count?.(typeof text === 'string' ? text.length : 0);
    return codes.handInFromText(text);
  };
  return { ...codes, handInFromText };
});

/**
 * What `read()` returns, and how many characters it looked at: one for each charCodeAt, the span each
 * indexOf scans, and the text given to JSON.parse and to the codes' decoder. findHandIns reads its
 * text through these alone (by code, not by index), so a loop that goes back over what it read shows
 * here as a count that grows faster than the text. Past `limit` every read throws, so a reader that
 * lost its bound stops there ({ result: null, count: Infinity }) instead of running for minutes.
 */
function countingReads(read, limit) {
  const { charCodeAt, indexOf } = String.prototype;
  const { parse } = JSON;
  let count = 0;
  const add = (n) => {
    count += n;
    if (count > limit) throw new RangeError(`more than ${limit} characters read`);
  };
  String.prototype.charCodeAt = function countedCharCodeAt(i) {
    add(1);
    return charCodeAt.call(this, i);
  };
  String.prototype.indexOf = function countedIndexOf(search, from = 0) {
    const at = indexOf.call(this, search, from);
    const start = Math.min(Math.max(0, Math.trunc(from) || 0), this.length);
    add((at === -1 ? this.length : at + String(search).length) - start);
    return at;
  };
  JSON.parse = (text, reviver) => {
    add(String(text).length);
    return parse(text, reviver);
  };
  decoding.count = add;
  try {
    const result = read();
    return { result, count };
  } catch (error) {
    if (count > limit) return { result: null, count: Infinity };
    throw error;
  } finally {
    Object.assign(String.prototype, { charCodeAt, indexOf });
    JSON.parse = parse;
    decoding.count = null;
  }
}

// The unit tests share their modules (isolate: false in vite.config.js), so the readers may have been
// loaded already with fflate and the decoder uncounted: they are loaded afresh, with the two above.
vi.resetModules();
const { readClassHandIns } = await import('../../src/homework/class/readClassHandIns.js');
const { findHandIns } = await import('../../src/homework/class/findHandIns.js');
const { gradeClassSync } = await import('../../src/homework/class/gradeClass.js');
const { lmsName } = await import('../../src/homework/class/lmsName.js');
const { handInToCode, makeHandIn } = await import('../../src/homework/sheetCodes.js');

const sheet = { version: 1, title: 'Fresnel – Übung 3', items: [{ question: 'exact-r' }, { question: 'metal-grazing' }, { question: 'brewster-predict' }] };
const handIn = (n, more = {}) => makeHandIn({ sheet, seed: `seed${n}`, name: `Student ${n}`, answers: ['0.05', 'towards-white', 56], time: `2026-01-0${1 + (n % 9)}T10:00:00.000Z`, ...more });
const json = (n) => strToU8(JSON.stringify(handIn(n)));
const code = (n) => handInToCode(handIn(n));
/** The most characters findHandIns may read per character of its text. */
const READS_PER_CHARACTER = 16;
const names = (read) => read.handIns.map((h) => h.data.name);
const sources = (list) => list.map((x) => x.source);

/** The offset of the n-th central directory header of a zip (to edit what it claims). */
function centralHeader(zip, n = 0) {
  let found = -1;
  for (let i = zip.length - 22; i >= 0; i -= 1) {
    if (zip[i] === 0x50 && zip[i + 1] === 0x4b && zip[i + 2] === 1 && zip[i + 3] === 2) {
      found = i;
    }
    if (zip[i] === 0x50 && zip[i + 1] === 0x4b && zip[i + 2] === 5 && zip[i + 3] === 6) {
      const view = new DataView(zip.buffer, zip.byteOffset);
      let p = view.getUint32(i + 16, true);
      for (let k = 0; k < n; k += 1) p += 46 + view.getUint16(p + 28, true) + view.getUint16(p + 30, true) + view.getUint16(p + 32, true);
      return p;
    }
  }
  return found;
}
const setU32 = (zip, at, value) => new DataView(zip.buffer, zip.byteOffset).setUint32(at, value, true);
/** The compressed size the n-th central directory header gives. */
const centralSize = (zip, n) => new DataView(zip.buffer, zip.byteOffset).getUint32(centralHeader(zip, n) + 20, true);

describe('an LMS zip', () => {
  it('reads folders per student, files nested deep, codes in .txt and zips inside folders; other files are refused by name', () => {
    const zip = zipSync({
      'Ada Lovelace_12345_assignsubmission_file_': { 'handin.json': json(1) },
      'Zoë Müller_12346_assignsubmission_file_': { work: { deeper: { 'code.txt': strToU8(`My code:\r\n${code(2)}\r\n`) } } },
      'Chloé Dubois_12347_assignsubmission_file_': { 'mine.zip': zipSync({ inner: { 'h.json': json(3), 'notes.docx': strToU8('x') } }) },
      'Noah Kim_12348_assignsubmission_file_': { 'report.pdf': strToU8('%PDF'), 'handin.json': json(4) },
      __MACOSX: { 'Noah Kim_12348_assignsubmission_file_': { '._handin.json': strToU8('\u0000\u0005binary') } },
    });
    const read = readClassHandIns({ files: [{ name: 'Homework 3-1234.zip', bytes: zip }] });
    expect(names(read).sort()).toEqual(['Student 1', 'Student 2', 'Student 3', 'Student 4']);
    expect(sources(read.handIns)).toContain('Homework 3-1234.zip/Chloé Dubois_12347_assignsubmission_file_/mine.zip/inner/h.json');
    expect(sources(read.handIns)).toContain('Homework 3-1234.zip/Zoë Müller_12346_assignsubmission_file_/work/deeper/code.txt, line 2');
    expect(read.refused.map((r) => r.source).sort()).toEqual([
      'Homework 3-1234.zip/Chloé Dubois_12347_assignsubmission_file_/mine.zip/inner/notes.docx',
      'Homework 3-1234.zip/Noah Kim_12348_assignsubmission_file_/report.pdf',
      'Homework 3-1234.zip/__MACOSX/Noah Kim_12348_assignsubmission_file_/._handin.json',
    ]);
    expect(read.refused.find((r) => r.source.endsWith('.pdf')).reason).toMatch(/\.pdf file is no hand-in/);
    expect(read.refused.find((r) => r.source.includes('__MACOSX')).reason).toMatch(/macOS/);
    expect(read.handIns.map((h) => lmsName(h.source)).sort()).toEqual(['Ada Lovelace', 'Chloé Dubois', 'Noah Kim', 'Zoë Müller']);
  });

  it('names the student from Canvas and Blackboard paths too, and nothing from a plain one', () => {
    expect(lmsName('subs.zip/lovelaceada_12345_67890_handin.json')).toBe('lovelaceada');
    expect(lmsName('subs.zip/lovelaceada_late_12345_67890_handin.json')).toBe('lovelaceada');
    expect(lmsName('gradebook.zip/Homework 3_alovelace_attempt_2026-01-02-10-00-00_handin.json')).toBe('alovelace');
    expect(lmsName('handin.json')).toBe('');
  });

  it('reads entry names written in UTF-8 without the UTF-8 flag, and Latin-1 ones', () => {
    const zip = zipSync({ 'a.json': json(1), 'b.json': json(2) });
    // fflate flags non-ASCII names; an old tool does not: clear the flag and write raw bytes.
    const utf8 = zipSync({ 'Zoë.json': json(1) });
    const flags = centralHeader(utf8) + 8;
    utf8[flags + 1] &= ~0x08;
    expect(sources(readClassHandIns({ files: [{ name: 'u.zip', bytes: utf8 }] }).handIns)).toEqual(['u.zip/Zoë.json']);
    const latin = zipSync({ 'Zo_.json': json(1) });
    latin[centralHeader(latin) + 46 + 2] = 0xeb; // ë in Latin-1
    expect(sources(readClassHandIns({ files: [{ name: 'l.zip', bytes: latin }] }).handIns)).toEqual(['l.zip/Zoë.json']);
    expect(readClassHandIns({ files: [{ name: 'z.zip', bytes: zip }] }).handIns).toHaveLength(2);
  });
});

describe('zip bombs and damaged zips', () => {
  it('a zip listing more entries than the cap is refused before anything is unpacked', () => {
    const many = Object.fromEntries(Array.from({ length: 2001 }, (_, i) => [`f${i}.json`, new Uint8Array(0)]));
    const read = readClassHandIns({ files: [{ name: 'many.zip', bytes: zipSync(many, { level: 0 }) }] });
    expect(read.handIns).toEqual([]);
    expect(read.refused).toEqual([{ source: 'many.zip', reason: expect.stringMatching(/lists 2001 entries, more than the 2000/) }]);
  });

  it('the entries of zips inside zips count against one cap, and what is past it is named', () => {
    const inner = zipSync(Object.fromEntries(Array.from({ length: 6 }, (_, i) => [`h${i}.json`, json(i)])));
    const read = readClassHandIns({ files: [{ name: 'class.zip', bytes: zipSync({ 'a.zip': inner, 'b.zip': inner }) }] }, { maxEntries: 10 });
    expect(read.handIns).toHaveLength(8);
    expect(read.refused).toHaveLength(4);
    for (const r of read.refused) expect(r.reason).toMatch(/cap on files unpacked/);
  });

  it('an entry that claims a huge size is refused from the directory, before it is unpacked', () => {
    const zip = zipSync({ 'ok.json': json(1), 'huge.json': json(2) });
    setU32(zip, centralHeader(zip, 1) + 24, 0xc0000000); // claims 3 GB
    const read = readClassHandIns({ files: [{ name: 'bomb.zip', bytes: zip }] });
    expect(names(read)).toEqual(['Student 1']);
    expect(read.refused).toEqual([{ source: 'bomb.zip/huge.json', reason: expect.stringMatching(/unpacks to 3072\.0 MB, more than the 4\.0 MB/) }]);
  });

  it('a small deflated entry that expands past what it claims is stopped there and refused, within one step', () => {
    // unzipBounded.js: an entry of at most one step (4096 compressed bytes) is inflated at once into a
    // buffer one byte longer than its claim; a longer one in steps, stopped at the step that passes
    // it, so it costs its claim plus one step's output (deflate's limit is 1032:1).
    const STEP = 4096;
    const claimed = 1000;
    for (const [megabytes, most] of [[2, claimed + 1], [8, claimed + 1032 * STEP]]) { // at once, and in steps
      const zeros = new Uint8Array(megabytes * 1024 * 1024);
      const zip = zipSync({ 'a.json': json(1), 'bomb.json': [zeros, { level: 9 }] });
      expect(zip.length).toBeLessThan(megabytes * 1100 + 2000); // a zip bomb's ratio, about 1000:1
      setU32(zip, centralHeader(zip, 1) + 24, claimed);
      const honest = json(1).length;
      Object.assign(inflated, { given: 0, written: 0 });
      const read = readClassHandIns({ files: [{ name: 'expand.zip', bytes: zip }] });
      expect(inflated.written, `${megabytes} MB`).toBeGreaterThan(honest); // the honest entry was inflated too
      expect(inflated.given - centralSize(zip, 0), `${megabytes} MB: compressed bytes of the bomb inflated`).toBeLessThanOrEqual(STEP);
      expect(inflated.written - honest, `${megabytes} MB: bytes the bomb wrote`).toBeLessThanOrEqual(most);
      expect(names(read)).toEqual(['Student 1']);
      expect(read.refused).toEqual([{ source: 'expand.zip/bomb.json', reason: expect.stringMatching(/zip bomb: it unpacks to more than the 1000 bytes/) }]);
    }
  });

  it('the unpacked total is capped across a zip and the zips inside it', () => {
    const big = zipSync({ 'a.json': json(1), 'b.json': json(2), 'c.json': json(3) });
    const read = readClassHandIns({ files: [{ name: 'c.zip', bytes: big }] }, { maxUnpackedBytes: json(1).length * 2 + 10 });
    expect(read.handIns).toHaveLength(2);
    expect(read.refused).toEqual([{ source: 'c.zip/c.json', reason: expect.stringMatching(/cap on bytes unpacked/) }]);
  });

  it('damaged, cut, encrypted, too deep or not a zip at all: refused by name, never thrown', () => {
    const stored = zipSync({ 'a.json': json(1) }, { level: 0 });
    const flipped = stored.slice();
    flipped[40] ^= 0xff; // a byte of a.json's data: its checksum no longer matches
    const encrypted = zipSync({ 'a.json': json(1) });
    encrypted[centralHeader(encrypted) + 8] |= 1;
    const deep = zipSync({ '1.zip': zipSync({ '2.zip': zipSync({ '3.zip': zipSync({ 'a.json': json(1) }) }) }) });
    const read = readClassHandIns({ files: [
      { name: 'flipped.zip', bytes: flipped },
      { name: 'cut.zip', bytes: stored.slice(0, stored.length - 30) },
      { name: 'encrypted.zip', bytes: encrypted },
      { name: 'deep.zip', bytes: deep },
      { name: 'photo.zip', bytes: strToU8('JFIF not a zip') },
      { name: 'empty.zip', bytes: zipSync({}) },
    ] });
    expect(read.handIns).toEqual([]);
    expect(Object.fromEntries(read.refused.map((r) => [r.source, r.reason]))).toEqual({
      'flipped.zip/a.json': expect.stringMatching(/checksum/),
      'cut.zip': expect.stringMatching(/no zip directory/),
      'encrypted.zip/a.json': expect.stringMatching(/encrypted/),
      'deep.zip/1.zip/2.zip/3.zip': expect.stringMatching(/3 deep at most/),
      'photo.zip': expect.stringMatching(/no zip directory/),
      'empty.zip': expect.stringMatching(/empty zip/),
    });
  });
});

describe('files and their caps', () => {
  it('a .json hand-in, a list of them, a .txt of codes in UTF-16; other files, empty and oversized ones named', () => {
    const utf16 = new Uint8Array([0xff, 0xfe, ...Array.from(`${code(3)}\n`, (c) => [c.charCodeAt(0), 0]).flat()]);
    const read = readClassHandIns({ files: [
      { name: 'a.json', bytes: json(1) },
      { name: 'list.json', bytes: strToU8(JSON.stringify([handIn(2), handIn(4)])) },
      { name: 'codes.txt', bytes: utf16 },
      { name: 'notes.md', bytes: strToU8(code(5)) },
      { name: 'empty.txt', bytes: new Uint8Array(0) },
      { name: 'big.txt', bytes: new Uint8Array(4 * 1024 * 1024 + 1) },
      { name: 'nothing.txt', bytes: strToU8('Dear professor, I attach my homework.') },
    ] });
    expect(sources(read.handIns)).toEqual(['a.json', 'list.json [1]', 'list.json [2]', 'codes.txt, line 1']);
    expect(Object.fromEntries(read.refused.map((r) => [r.source, r.reason]))).toEqual({
      'notes.md': expect.stringMatching(/\.md file is no hand-in/),
      'empty.txt': 'an empty file.',
      'big.txt': expect.stringMatching(/more than the 4\.0 MB/),
      'nothing.txt': expect.stringMatching(/holds no hand-in/),
    });
  });

  it('stops at the cap on hand-ins, naming what is left', () => {
    const read = readClassHandIns({ text: [1, 2, 3, 4].map(code).join('\n') }, { maxHandIns: 2 });
    expect(read.handIns).toHaveLength(2);
    expect(read.refused).toHaveLength(2);
    expect(read.refused[0].reason).toMatch(/cap on hand-ins/);
  });
});

describe('codes and JSON in pasted text', () => {
  it('finds codes one per line, mixed with text, in CSV fields and in an LMS export', () => {
    const text = [
      'Name,Submission,Comment',
      `"Lovelace, Ada","${code(1)}","late, sorry"`,
      `Zoë;${code(2)};ok`,
      `Online text: <p>${code(3)}</p>`,
      `${code(4)} Thanks!`,
    ].join('\r\n');
    const read = findHandIns(text, 'pasted text');
    expect(read.refused).toEqual([]);
    expect(names(read)).toEqual(['Student 1', 'Student 2', 'Student 3', 'Student 4']);
    expect(sources(read.handIns)).toEqual(['pasted text, line 2', 'pasted text, line 3', 'pasted text, line 4', 'pasted text, line 5']);
  });

  it('joins a code that mail wrapped, quoted with "> ", or ended lines of with quoted-printable "="', () => {
    const wrapped = code(1).match(/.{1,76}/g);
    const text = [
      'On Monday Ada wrote:',
      `> ${wrapped.join('\n> ')}`,
      '> Best, Ada',
      '',
      `${code(2).match(/.{1,75}/g).join('=\n')}`,
      'Cheers',
      code(3).match(/.{1,60}/g).join('\r\n'),
      'Kind regards',
    ].join('\n');
    const read = findHandIns(text, 'mail.txt');
    expect(read.refused).toEqual([]);
    expect(read.handIns.map((h) => h.data)).toEqual([handIn(1), handIn(2), handIn(3)]);
  });

  it('refuses a code cut in the middle with its line and reason, while the codes around it are graded', () => {
    const cut = code(2).slice(0, 300);
    const text = `${code(1)}\n${cut}\n${code(3)}\nFLH1.\n`;
    const read = readClassHandIns({ text });
    expect(names(read)).toEqual(['Student 1', 'Student 3']);
    expect(read.refused).toEqual([
      { source: 'pasted text, line 2', reason: expect.stringMatching(/damaged|not readable JSON/) },
      { source: 'pasted text, line 4', reason: 'FLH1. is followed by no code.' },
    ]);
    expect(read.refused[0].reason).toMatch(/cut short/);
    const grades = gradeClassSync(sheet, read.handIns);
    expect(grades.graded.map((g) => g.result.name)).toEqual(['Student 1', 'Student 3']);
  });

  it('finds hand-ins as JSON in text, pretty-printed, on one line, or in a CSV cell with its quotes doubled', () => {
    const csvCell = `"${JSON.stringify(handIn(3)).replaceAll('"', '""')}"`;
    const text = `Here is mine:\n${JSON.stringify(handIn(1), null, 2)}\nand Zoë's: ${JSON.stringify(handIn(2))} (sent late)\n`;
    expect(findHandIns(text, 't').handIns.map((h) => h.data)).toEqual([handIn(1), handIn(2)]);
    expect(findHandIns(`name,file\nChloé,${csvCell}\n`, 'c').handIns.map((h) => h.data)).toEqual([handIn(3)]);
    const cutJson = JSON.stringify(handIn(4)).slice(0, 200);
    const mixed = findHandIns(`${cutJson}\n${JSON.stringify(handIn(5))}`, 'm');
    expect(mixed.handIns.map((h) => h.data)).toEqual([handIn(5)]);
    expect(mixed.refused).toEqual([{ source: 'm, line 1', reason: expect.stringMatching(/cut short/) }]);
  });

  it('a name that holds a code or the hand-in kind does not make a second hand-in', () => {
    const sly = handIn(1, { name: `FLH1.abc "fresnel-lab-hand-in" ${code(9).slice(0, 20)}` });
    const read = findHandIns(JSON.stringify(sly), 's');
    expect(read.handIns.map((h) => h.data)).toEqual([sly]);
    expect(read.refused).toEqual([]);
  });

  it('an empty paste is nothing; a paste of thousands of prefixes lists a thousand refusals and counts the rest', () => {
    expect(readClassHandIns({ text: '  \n ' })).toEqual({ handIns: [], refused: [] });
    const read = findHandIns('FLH1. '.repeat(5000), 'p');
    expect(read.refused).toHaveLength(1001);
    expect(read.refused[1000].reason).toMatch(/and 4000 more/);
  });

  it('a paste built to be slow is read in linear steps (a megabyte of each: kinds, prefixes, broken codes, backslashes)', () => {
    const M = 1024 * 1024;
    const texts = [
      '"fresnel-lab-hand-in"'.repeat(M / 21), '{"kind":"fresnel-lab-hand-in",'.repeat(M / 30), 'FLH1.a\n'.repeat(M / 7),
      `FLH1.${'a\n'.repeat(M / 2)}`, `{${'\\'.repeat(M)}"fresnel-lab-hand-in"}`, ('\\'.repeat(999) + '"').repeat(M / 1000),
      '""fresnel-lab-hand-in""'.repeat(M / 23),
    ];
    for (const [i, text] of texts.entries()) {
      // Each character is looked at a bounded number of times; quadratic, this would be about a million.
      const { result: read, count } = countingReads(() => findHandIns(text, 'p'), READS_PER_CHARACTER * text.length);
      expect(count / text.length, `text ${i + 1}: characters read per character`).toBeLessThanOrEqual(READS_PER_CHARACTER);
      expect(read.handIns).toEqual([]);
      expect(read.refused.length).toBeGreaterThan(0);
      expect(read.refused.length).toBeLessThanOrEqual(1001);
    }
  });
  it('counts what it reads: a hand-in is read once, not once per character', () => {
    const text = `Dear lecturer,\n${code(1)}\nthanks`;
    const given = decoding.given;
    const { result, count } = countingReads(() => findHandIns(text, 'p'), READS_PER_CHARACTER * text.length);
    expect(decoding.given - given).toBeGreaterThanOrEqual(code(1).length); // the decoder's reading is counted
    expect(count).toBeGreaterThan(text.length + code(1).length); // and the scan's
    expect(count).toBeLessThanOrEqual(READS_PER_CHARACTER * text.length);
    expect(result.handIns.map((h) => h.data)).toEqual([handIn(1)]);
  });
});

