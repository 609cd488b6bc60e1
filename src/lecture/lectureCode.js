// @ts-check
// A lecture in a link: ?lecture=L1.<base64url of the raw DEFLATE of its JSON> (RFC 1951, RFC 4648
// §5), a fraction of the JSON's length, and "." and base64url's characters survive any link. Reading
// it is bounded twice: the code's length before anything is done, and the inflated size (a small code
// that inflates to a book is refused), so a link from anyone costs little. This module turns a code
// into data only, with no words and no reading of the lecture (lectureLink.js and readLecture.js do
// that), so that a page can find the language a lecture carries before it loads any words.
import { inflateSync } from 'fflate';
import { isObject, own } from '../host/own.js';
import { languageById } from '../i18n/languages.js';

export const LECTURE_CODE_PREFIX = 'L1.';
export const MAX_CODE = 100_000; // characters; a full lecture with text on every item is a few kilobytes
export const MAX_JSON = 400_000; // bytes inflated

/**
 * Why a code could not be decoded: a key of the catalogue's "lecture" namespace, and its numbers.
 * @typedef {{ ok: false, problem: 'codeNotText' | 'codeBadPercent' | 'codeNoPrefix' | 'codeTooLong' | 'codeBadCharacters'
 *   | 'codeTooBig' | 'codeDamaged', length?: number, data?: undefined }} Undecoded
 */

/**
 * The JSON of a code, or of a link holding one, not yet read as a lecture: { ok: true, data } or
 * { ok: false, problem } (Undecoded). Never throws. (Each member names the other's fields, undefined,
 * so that the loose project, which cannot narrow on `ok`, reads both.)
 * @param {unknown} text
 * @returns {{ ok: true, data: unknown, problem?: undefined, length?: undefined } | Undecoded}
 */
export function lectureCodeData(text) {
  if (typeof text !== 'string') return { ok: false, problem: 'codeNotText' };
  let code = text.trim();
  const inLink = /[?&]lecture=([^&#\s]*)/.exec(code);
  if (inLink) {
    try {
      code = decodeURIComponent(inLink[1]);
    } catch {
      return { ok: false, problem: 'codeBadPercent' };
    }
  }
  code = code.replace(/\s+/g, ''); // mail wraps long links
  if (!code.startsWith(LECTURE_CODE_PREFIX)) return { ok: false, problem: 'codeNoPrefix' };
  if (code.length > MAX_CODE) return { ok: false, problem: 'codeTooLong', length: code.length };
  const body = code.slice(LECTURE_CODE_PREFIX.length);
  if (!/^[A-Za-z0-9_-]*$/.test(body)) return { ok: false, problem: 'codeBadCharacters' };
  try {
    const bytes = Uint8Array.from(atob(body.replace(/-/g, '+').replace(/_/g, '/')), (c) => c.charCodeAt(0));
    // One byte of room: a stream that runs past the cap is refused, not cut.
    const out = inflateSync(bytes, { out: new Uint8Array(MAX_JSON + 1) });
    if (out.length > MAX_JSON) return { ok: false, problem: 'codeTooBig' };
    return { ok: true, data: JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(out)) };
  } catch {
    return { ok: false, problem: 'codeDamaged' };
  }
}

/**
 * The language a lecture's code carries, where it is one the lab speaks (readLecture's rule), else
 * null: a lecture link opens in the language it was made in.
 * @param {unknown} text
 * @returns {string | null}
 */
export function lectureCodeLanguage(text) {
  const decoded = lectureCodeData(text);
  const lang = decoded.ok && isObject(decoded.data) ? own(decoded.data, 'lang') : undefined;
  return typeof lang === 'string' && languageById(lang) ? lang : null;
}
