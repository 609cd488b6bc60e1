// @ts-check
// A lecture in a link: ?lecture=L1.<base64url of the raw DEFLATE of its JSON> (lectureCode.js reads
// a code into data, bounded). What the code holds is then read as untrusted data (readLecture.js),
// and what could not be decoded is said in the page's language.
import { deflateSync } from 'fflate';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { readLecture } from './readLecture.js';
import { fixed } from '../ui/format.js';
import { LECTURE_CODE_PREFIX, MAX_CODE, MAX_JSON, lectureCodeData } from './lectureCode.js';

const t = messages('lecture', english);

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
  const decoded = lectureCodeData(text);
  if (decoded.ok) return readLecture(decoded.data);
  const max = decoded.problem === 'codeTooBig' ? MAX_JSON : MAX_CODE;
  const args = { prefix: LECTURE_CODE_PREFIX, length: fixed(decoded.length ?? 0, 0), max: fixed(max, 0) };
  return { ok: false, problems: [t(decoded.problem, args)] };
}
