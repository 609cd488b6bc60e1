// @ts-check
// A lecture in a link: ?lecture=L1.<base64url of the raw DEFLATE of its JSON> (RFC 1951, RFC 4648
// §5), a fraction of the JSON's length, and "." and base64url's characters survive any link. Reading
// it is bounded twice: the code's length before anything is done, and the inflated size (a small code
// that inflates to a book is refused), so a link from anyone costs little. What the code holds is
// then read as untrusted data (readLecture.js).
import { deflateSync, inflateSync } from 'fflate';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { readLecture } from './readLecture.js';
import { fixed } from '../ui/format.js';

const t = messages('lecture', english);

export const LECTURE_CODE_PREFIX = 'L1.';
const MAX_CODE = 100_000; // characters; a full lecture with text on every item is a few kilobytes
const MAX_JSON = 400_000; // bytes inflated

const toBase64Url = (/** @type {Uint8Array} */ bytes) => {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
};

/**
 * The code of a lecture (as readLecture gives it), for ?lecture=.
 * @param {import('./readLecture.js').Lecture} lecture
 */
export function lectureToCode(lecture) {
  return LECTURE_CODE_PREFIX + toBase64Url(deflateSync(new TextEncoder().encode(JSON.stringify(lecture)), { level: 9 }));
}

/**
 * { ok: true, lecture, problems } or { ok: false, problems }, from a code or a link holding one. Never throws.
 * @param {unknown} text
 * @returns {import('./readLecture.js').ReadLecture}
 */
export function lectureFromCode(text) {
  if (typeof text !== 'string') return { ok: false, problems: [t('codeNotText')] };
  let code = text.trim();
  const inLink = /[?&]lecture=([^&#\s]*)/.exec(code);
  if (inLink) {
    try {
      code = decodeURIComponent(inLink[1]);
    } catch {
      return { ok: false, problems: [t('codeBadPercent')] };
    }
  }
  code = code.replace(/\s+/g, ''); // mail wraps long links
  if (!code.startsWith(LECTURE_CODE_PREFIX)) {
    return { ok: false, problems: [t('codeNoPrefix', { prefix: LECTURE_CODE_PREFIX })] };
  }
  if (code.length > MAX_CODE) {
    return { ok: false, problems: [t('codeTooLong', { length: fixed(code.length, 0), max: fixed(MAX_CODE, 0) })] };
  }
  const body = code.slice(LECTURE_CODE_PREFIX.length);
  if (!/^[A-Za-z0-9_-]*$/.test(body)) {
    return { ok: false, problems: [t('codeBadCharacters')] };
  }
  /** @type {unknown} */
  let json;
  try {
    const bytes = Uint8Array.from(atob(body.replace(/-/g, '+').replace(/_/g, '/')), (c) => c.charCodeAt(0));
    // One byte of room: a stream that runs past the cap is refused, not cut.
    const out = inflateSync(bytes, { out: new Uint8Array(MAX_JSON + 1) });
    if (out.length > MAX_JSON) return { ok: false, problems: [t('codeTooBig', { max: fixed(MAX_JSON, 0) })] };
    json = JSON.parse(new TextDecoder('utf-8', { fatal: true }).decode(out));
  } catch {
    return { ok: false, problems: [t('codeDamaged')] };
  }
  return readLecture(json);
}
