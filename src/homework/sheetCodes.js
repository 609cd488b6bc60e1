// @ts-check
// Sheets and handed-in files as text: a sheet travels in a link (?sheet=CODE) and a handed-in file
// as JSON or as a code a student can paste into a message. A code is the JSON in base64url
// (RFC 4648 §5), so it survives links, e-mail and LMS text boxes; a handed-in code starts with
// HAND_IN_PREFIX so the two cannot be confused. Decoding only turns text into data: readSheet.js
// decides whether the data is a sheet.
import { SHEET_VERSION } from './readSheet.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

export const HAND_IN_PREFIX = 'FLH1.';
export const HAND_IN_KIND = 'fresnel-lab-hand-in';
const MAX_CODE = 200_000; // far above any real sheet (40 items); stops a pasted book early

/**
 * Text decoded into data, not yet read (readSheet, gradeHandIn); damaged: the code's characters or
 * bytes are broken (a code cut short when copied, most often). (The other member's fields are
 * there, undefined, so that the loose project, which cannot narrow on `ok`, reads both.)
 * @typedef {{ ok: true, data: unknown, problems?: undefined, damaged?: undefined }
 *   | { ok: false, problems: string[], damaged?: boolean, data?: undefined }} Decoded
 */

/**
 * @param {string} text
 */
function toBase64Url(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = '';
  for (const byte of bytes) binary += String.fromCharCode(byte);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** Why a code is damaged: 'badCharacters' or 'notText' (a key of the catalogue's codes.<what>.*). */
class Damaged extends Error {}

/**
 * @param {string} text
 */
function fromBase64Url(text) {
  // Mail and chat programs wrap long codes; some tools add base64 padding. Both are harmless.
  const code = text.replace(/\s+/g, '').replace(/=+$/, '');
  if (!/^[A-Za-z0-9_-]*$/.test(code)) throw new Damaged('badCharacters');
  try {
    const binary = atob(code.replace(/-/g, '+').replace(/_/g, '/'));
    return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(binary, (c) => c.charCodeAt(0)));
  } catch {
    throw new Damaged('notText');
  }
}

/**
 * what: 'sheetLink', 'handInCode' or 'handInFile', the catalogue's codes.<what>.* (each a whole sentence).
 * @param {string} text
 * @param {string} what
 * @returns {Decoded}
 */
function parseJson(text, what) {
  try {
    return { ok: true, data: /** @type {unknown} */ (JSON.parse(text)) };
  } catch {
    return { ok: false, problems: [t(`codes.${what}.notJson`)] };
  }
}

// A code or a file is text: anything else (a number, an object whose toString throws) is none.
const asText = (/** @type {unknown} */ raw) => (typeof raw === 'string' ? raw : '');

/**
 * damaged: true where the code's characters or bytes are broken (a code cut short when copied, most often).
 * @param {unknown} code
 * @param {string} what
 * @returns {Decoded}
 */
function decode(code, what) {
  const text = asText(code).trim();
  if (!text) return { ok: false, problems: [t(`codes.${what}.none`)] };
  if (text.length > MAX_CODE) return { ok: false, problems: [t(`codes.${what}.tooLong`, { length: text.length })] };
  try {
    return parseJson(fromBase64Url(text), what);
  } catch (error) {
    if (!(error instanceof Damaged)) throw error;
    return { ok: false, damaged: true, problems: [t(`codes.${what}.${error.message}`)] };
  }
}

/** The code of a sheet, for ?sheet=CODE. */
export const sheetToCode = (/** @type {unknown} */ sheet) => toBase64Url(JSON.stringify(sheet));

/** { ok: true, data } (still to be read by readSheet) or { ok: false, problems }. */
export const sheetFromCode = (/** @type {unknown} */ code) => decode(code, 'sheetLink');

/**
 * A handed-in file's content: what the student answered, for which sheet and seed, how many
 * tries each answer took (shown to the lecturer, not graded), and when.
 * @param {{ sheet: unknown, seed: string, name?: string, answers: unknown[], attempts?: number[], time?: string }} handIn
 */
export function makeHandIn({ sheet, seed, name = '', answers, attempts = answers.map(() => 0), time = new Date().toISOString() }) {
  return { kind: HAND_IN_KIND, version: SHEET_VERSION, sheet, seed, name, answers, attempts, time };
}

export const handInToCode = (/** @type {unknown} */ handIn) => HAND_IN_PREFIX + toBase64Url(JSON.stringify(handIn));

/**
 * Text a lecturer pasted or a file they picked: a handed-in code, or the JSON of a handed-in file.
 * { ok: true, data } (still to be graded by gradeHandIn) or { ok: false, problems }.
 * @param {unknown} text
 * @returns {Decoded}
 */
export function handInFromText(text) {
  const trimmed = asText(text).trim();
  if (trimmed.startsWith('{')) return parseJson(trimmed, 'handInFile');
  if (trimmed.startsWith(HAND_IN_PREFIX)) return decode(trimmed.slice(HAND_IN_PREFIX.length), 'handInCode');
  if (!trimmed) return { ok: false, problems: [t('codes.nothing')] };
  return { ok: false, problems: [t('codes.neither', { prefix: HAND_IN_PREFIX })] };
}
