// @ts-check
// Every hand-in in a text: a handed-in file's JSON, a list of codes one per line, codes mixed with
// other text (a mail, an LMS's text export, a CSV with quoted fields). Each hand-in found is
// { source, data } with the line it starts on; each that is there but cannot be read (a code cut
// in the middle, JSON cut short) is refused with the same source and the reason. Nothing found in a
// text that is not empty is refused too.
//
// Codes: mail programs wrap long lines, quote them with "> ", and quoted-printable mail ends a
// wrapped line with "=". A code is the base64url of JSON (sheetCodes.js), and a proper prefix of a
// JSON object is never valid JSON, so the code's end is the first place, among the ends of its
// line pieces, where it decodes to a JSON object: text that follows it (a name, "Thanks") is not
// taken in, and a line break inside it does not cut it. Cost: a piece is decoded only when its
// last group of four characters decodes to "}", so a wrapped code is decoded about once.
import { HAND_IN_KIND, HAND_IN_PREFIX, handInFromText } from '../sheetCodes.js';
import { fixed } from '../../ui/format.js';
import { isObject } from '../../host/own.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const t = messages('class', english);
const MAX_CODE_CHARS = 200_000; // as sheetCodes.js: far above any sheet
const MAX_JSON_CHARS = 1_000_000; // a hand-in's JSON: its sheet has at most 40 items of 24 values
const MARK = `"${HAND_IN_KIND}"`; // the value of a hand-in's "kind"
const full = () => t('find.full');
const MAX_REFUSALS = 1000; // listed one by one, per text

/**
 * @typedef {{ source: string, data: unknown }} HandIn
 * @typedef {{ source: string, reason: string }} Refusal
 * @typedef {{ data: object, end: number, reason?: undefined } | { reason: string, data?: undefined, end?: undefined }} Code
 *   A code read: its data and where it ends, or why it cannot be read.
 * @typedef {{ start: number, end?: number, data?: unknown, reason?: string }} Found A hand-in found in the text (its data,
 *   and where its JSON ends), or one that is there and cannot be read (the reason).
 */

/** @type {(c: number) => boolean} */
const isCodeChar = (c) => (c >= 48 && c <= 57) || (c >= 65 && c <= 90) || (c >= 97 && c <= 122) || c === 45 || c === 95;
/** @type {(c: number) => boolean} */
const isSpace = (c) => c === 32 || c === 9 || c === 10 || c === 13 || c === 12 || c === 0xa0;

/**
 * The line (from 1) each position is on, by binary search over the line starts.
 * @param {string} text
 * @returns {(position: number) => number}
 */
function lineFinder(text) {
  const starts = [0];
  for (let i = text.indexOf('\n'); i !== -1; i = text.indexOf('\n', i + 1)) starts.push(i + 1);
  return (position) => {
    let lo = 0;
    let hi = starts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (starts[mid] <= position) lo = mid;
      else hi = mid - 1;
    }
    return lo + 1;
  };
}

/**
 * Whether a base64url text's last byte is "}" (the end of a JSON object), from its last group alone.
 * @param {string} code
 */
function endsInBrace(code) {
  const rest = code.length % 4;
  if (rest === 1) return false;
  const group = code.slice(code.length - (rest || 4)).replace(/-/g, '+').replace(/_/g, '/');
  try {
    return atob(group + '='.repeat((4 - (group.length % 4)) % 4)).endsWith('}');
  } catch {
    return false;
  }
}

/**
 * The code that starts after a prefix at `start`, read up to `limit`: { data, end } for the first end
 * at which it decodes to a JSON object, or { reason } why none does (worked out only when `explain`:
 * decoding a damaged code throws inside sheetCodes.js, and a text of a million broken codes would
 * spend half a minute on reasons that are counted, not listed).
 * @param {string} text
 * @param {number} start
 * @param {number} limit
 * @param {boolean} explain
 * @returns {Code}
 */
function readCode(text, start, limit, explain) {
  let code = '';
  /** @type {[number, number][]} [length of code, position in text after it] */
  const ends = [];
  let run = start;
  let lineStart = false;
  const close = (/** @type {number} */ i) => {
    if (i > run) code += text.slice(run, i);
    run = i;
    if (code.length && (!ends.length || ends[ends.length - 1][0] !== code.length)) ends.push([code.length, i]);
  };
  let i = start;
  for (; i < limit && code.length + i - run <= MAX_CODE_CHARS; i += 1) {
    const c = text.charCodeAt(i);
    if (isCodeChar(c)) {
      lineStart = false;
      continue;
    }
    close(i);
    if (isSpace(c)) {
      if (c === 10) lineStart = true;
    } else if (c === 62 && lineStart) { // ">" that quotes a line in a reply
      // skipped: the code may go on after it
    } else if (c === 61 && /^=\r?\n/.test(text.slice(i, i + 3))) { // "=" that ends a quoted-printable line
      i = text.indexOf('\n', i);
      lineStart = true;
    } else {
      break; // any other character (a quote, a comma, "<", "=" padding) ends a code
    }
    run = i + 1;
  }
  close(Math.min(i, limit));
  for (const [length, end] of ends) {
    const piece = code.slice(0, length);
    if (!endsInBrace(piece)) continue;
    const read = handInFromText(HAND_IN_PREFIX + piece);
    if (read.ok && isObject(read.data)) return { data: read.data, end };
  }
  if (!ends.length) return { reason: t('find.noCode', { prefix: HAND_IN_PREFIX }) };
  if (!explain) return { reason: t('find.codeUnreadable') };
  const first = handInFromText(HAND_IN_PREFIX + code.slice(0, ends[0][0]));
  if (first.ok) return { reason: t('find.codeNotHandIn') };
  const reason = first.problems.join(' ');
  // A damaged code's reason already asks whether it was cut short; any other does not.
  return { reason: first.damaged ? reason : t('find.cutShort', { reason }) };
}

// The loops read the text by code (charCodeAt), one way for all of them, which classReading.test.js
// counts to hold them to a bounded number of reads per character: " \ { } [ ]
const QUOTE = 34;
const BACKSLASH = 92;
const OPEN = 123;
const CLOSE = 125;
const OPEN_LIST = 91;
const CLOSE_LIST = 93;

/**
 * Whether the character at i is escaped by an odd run of backslashes (counted up to 1,000).
 * @param {string} text
 * @param {number} i
 */
function escaped(text, i) {
  let n = 0;
  for (let j = i - 1; j >= 0 && text.charCodeAt(j) === BACKSLASH && n < 1000; j -= 1) n += 1;
  return n % 2 === 1;
}

/**
 * The "{" that opens the object holding position `at`, searched back no further than `floor`; -1 if none.
 * @param {string} text
 * @param {number} at
 * @param {number} floor
 */
function objectStart(text, at, floor) {
  let depth = 0;
  let inString = false;
  for (let i = at - 1; i >= floor; i -= 1) {
    const c = text.charCodeAt(i);
    if (c === QUOTE) {
      if (!escaped(text, i)) inString = !inString;
    } else if (inString) continue;
    else if (c === CLOSE || c === CLOSE_LIST) depth += 1;
    else if (c === OPEN || c === OPEN_LIST) {
      if (depth === 0) return c === OPEN ? i : -1;
      depth -= 1;
    }
  }
  return -1;
}

/**
 * The "}" that closes the object opened at `start`, searched no further than `ceiling`; -1 if none.
 * @param {string} text
 * @param {number} start
 * @param {number} ceiling
 */
function objectEnd(text, start, ceiling) {
  let depth = 0;
  let inString = false;
  for (let i = start; i < ceiling; i += 1) {
    const c = text.charCodeAt(i);
    if (inString) {
      if (c === BACKSLASH) i += 1;
      else if (c === QUOTE) inString = false;
    } else if (c === QUOTE) inString = true;
    else if (c === OPEN || c === OPEN_LIST) depth += 1;
    else if (c === CLOSE || c === CLOSE_LIST) {
      depth -= 1;
      if (depth === 0) return i;
    }
  }
  return -1;
}

/**
 * Hand-ins as JSON inside a text, found by their kind: [{ start, end, data } | { start, reason }].
 * Each search stops at the next one's kind, so every character is looked at a bounded number of times.
 * @param {string} text
 * @returns {Found[]}
 */
function findJson(text) {
  // Each reason written once: a text can hold a million broken hand-ins.
  const noStart = t('find.jsonNoStart');
  const cut = t('find.jsonCut');
  const unreadable = t('find.jsonUnreadable');
  /** @type {Found[]} */
  const found = [];
  /** @type {number[]} */
  const marks = [];
  for (let m = text.indexOf(MARK); m !== -1; m = text.indexOf(MARK, m + 1)) if (!escaped(text, m)) marks.push(m);
  let floor = 0;
  marks.forEach((m, k) => {
    if (m < floor) return; // inside a hand-in already read (a name that quotes the kind)
    // A hand-in holds one kind (a name that quotes it has its quotes escaped), so the search for its
    // "{" stops at the kind before it, as the search for its "}" stops at the kind after it.
    const start = objectStart(text, m, Math.max(floor, m - MAX_JSON_CHARS, k > 0 ? marks[k - 1] + MARK.length : 0));
    if (start < 0) {
      found.push({ start: m, reason: noStart });
      return;
    }
    const ceiling = Math.min(text.length, start + MAX_JSON_CHARS, k + 1 < marks.length ? marks[k + 1] : Infinity);
    const end = objectEnd(text, start, ceiling);
    if (end < 0) {
      found.push({ start, reason: cut });
      return;
    }
    try {
      found.push({ start, end: end + 1, data: /** @type {unknown} */ (JSON.parse(text.slice(start, end + 1))) });
      floor = end + 1;
    } catch {
      found.push({ start, reason: unreadable });
    }
  });
  return found;
}

/**
 * Every hand-in in `text`, which came from `source` (a file's path, or "pasted text"); at most
 * `maxHandIns` (what is left of the class's cap) are read, the rest refused. Never throws on any text.
 * @param {string} text
 * @param {string} source
 * @param {{ maxHandIns?: number }} [options]
 * @returns {{ handIns: HandIn[], refused: Refusal[] }}
 */
export function findHandIns(text, source, { maxHandIns = Infinity } = {}) {
  /** @type {HandIn[]} */
  const handIns = [];
  /** @type {Refusal[]} */
  const refused = [];
  const trimmed = text.trim();
  if (!trimmed) return { handIns, refused };
  // A whole handed-in file, or a list of them.
  if (trimmed.startsWith('{') || trimmed.startsWith('[')) {
    /** @type {unknown} */
    let data;
    try {
      data = JSON.parse(trimmed);
    } catch { /* JSON with other text around it, or cut: searched below */ }
    const list = Array.isArray(data) ? data.map((item, i) => ({ source: `${source} [${i + 1}]`, data: item })) : [];
    if (isObject(data)) list.push({ source, data });
    handIns.push(...list.slice(0, maxHandIns));
    if (list.length > maxHandIns) refused.push({ source: `${source} [${maxHandIns + 1}–${list.length}]`, reason: full() });
    if (data !== undefined && (handIns.length || refused.length)) return { handIns, refused };
  }
  // A CSV cell doubles the quotes of the JSON in it ("{""kind"":…}"): read that JSON undoubled.
  const scanned = text.includes(`"${MARK}"`) ? text.replaceAll('""', '"') : text;
  const lineOf = lineFinder(scanned);
  const found = findJson(scanned);
  const taken = found.flatMap((f) => (f.end === undefined ? [] : [{ start: f.start, end: f.end }]));
  const inside = (/** @type {number} */ i) => taken.some((f) => f.start <= i && i < f.end);
  let failed = 0;
  for (let p = scanned.indexOf(HAND_IN_PREFIX); p !== -1;) {
    const next = scanned.indexOf(HAND_IN_PREFIX, p + HAND_IN_PREFIX.length);
    if (!inside(p)) {
      // Only the first MAX_REFUSALS of them can be listed, so only they are explained.
      const code = readCode(scanned, p + HAND_IN_PREFIX.length, next === -1 ? scanned.length : next, failed < MAX_REFUSALS);
      if (code.reason) failed += 1;
      found.push({ start: p, ...code });
    }
    p = next;
  }
  found.sort((a, b) => a.start - b.start);
  let unlisted = 0;
  const where = (/** @type {Found} */ f) => t('source.line', { source, line: lineOf(f.start) });
  for (const f of found) {
    const reason = f.reason ?? (handIns.length >= maxHandIns ? full() : null);
    if (!reason) handIns.push({ source: where(f), data: f.data });
    else if (refused.length < MAX_REFUSALS) refused.push({ source: where(f), reason });
    else unlisted += 1;
  }
  // A text of nothing but "FLH1." would list a refusal for each: past a thousand, they are counted.
  if (unlisted) refused.push({ source, reason: t('find.unlisted', { count: unlisted, n: fixed(unlisted, 0) }) });
  if (!handIns.length && !refused.length) refused.push({ source, reason: t('find.none', { prefix: HAND_IN_PREFIX }) });
  return { handIns, refused };
}
