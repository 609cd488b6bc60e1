// Sheets and handed-in files as text: a sheet travels in a link (?sheet=CODE) and a handed-in file
// as JSON or as a code a student can paste into a message. A code is the JSON in base64url
// (RFC 4648 §5), so it survives links, e-mail and LMS text boxes; a handed-in code starts with
// HAND_IN_PREFIX so the two cannot be confused. Decoding only turns text into data: readSheet.js
// decides whether the data is a sheet.
import { SHEET_VERSION } from './readSheet.js';

export const HAND_IN_PREFIX = 'FLH1.';
export const HAND_IN_KIND = 'fresnel-lab-hand-in';
const MAX_CODE = 200_000; // far above any real sheet (40 items); stops a pasted book early

function toBase64Url(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = '';
  for (const byte of bytes) binary += String.fromCharCode(byte);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

class Damaged extends Error {}

function fromBase64Url(text) {
  // Mail and chat programs wrap long codes; some tools add base64 padding. Both are harmless.
  const code = text.replace(/\s+/g, '').replace(/=+$/, '');
  if (!/^[A-Za-z0-9_-]*$/.test(code)) throw new Damaged('it holds characters a code never has');
  try {
    const binary = atob(code.replace(/-/g, '+').replace(/_/g, '/'));
    return new TextDecoder('utf-8', { fatal: true }).decode(Uint8Array.from(binary, (c) => c.charCodeAt(0)));
  } catch {
    throw new Damaged('it does not decode to text');
  }
}

function parseJson(text, what) {
  try {
    return { ok: true, data: JSON.parse(text) };
  } catch {
    return { ok: false, problems: [`This ${what} is not readable JSON.`] };
  }
}

// A code or a file is text: anything else (a number, an object whose toString throws) is none.
const asText = (raw) => (typeof raw === 'string' ? raw : '');

function decode(code, what) {
  const text = asText(code).trim();
  if (!text) return { ok: false, problems: [`No ${what} was given.`] };
  if (text.length > MAX_CODE) return { ok: false, problems: [`This ${what} is too long to be one (${text.length} characters).`] };
  try {
    return parseJson(fromBase64Url(text), what);
  } catch (error) {
    if (!(error instanceof Damaged)) throw error;
    return { ok: false, problems: [`This ${what} is damaged: ${error.message} (was it cut short when copied?).`] };
  }
}

/** The code of a sheet, for ?sheet=CODE. */
export const sheetToCode = (sheet) => toBase64Url(JSON.stringify(sheet));

/** { ok: true, data } (still to be read by readSheet) or { ok: false, problems }. */
export const sheetFromCode = (code) => decode(code, 'sheet link');

/**
 * A handed-in file's content: what the student answered, for which sheet and seed, how many
 * tries each answer took (shown to the lecturer, not graded), and when.
 */
export function makeHandIn({ sheet, seed, name = '', answers, attempts = answers.map(() => 0), time = new Date().toISOString() }) {
  return { kind: HAND_IN_KIND, version: SHEET_VERSION, sheet, seed, name, answers, attempts, time };
}

export const handInToCode = (handIn) => HAND_IN_PREFIX + toBase64Url(JSON.stringify(handIn));

/**
 * Text a lecturer pasted or a file they picked: a handed-in code, or the JSON of a handed-in file.
 * { ok: true, data } (still to be graded by gradeHandIn) or { ok: false, problems }.
 */
export function handInFromText(text) {
  const trimmed = asText(text).trim();
  if (trimmed.startsWith('{')) return parseJson(trimmed, 'handed-in file');
  if (trimmed.startsWith(HAND_IN_PREFIX)) return decode(trimmed.slice(HAND_IN_PREFIX.length), 'handed-in code');
  if (!trimmed) return { ok: false, problems: ['Nothing was given: paste a handed-in code or choose a handed-in file.'] };
  return { ok: false, problems: [`This is neither a handed-in file (JSON) nor a handed-in code (it starts with ${HAND_IN_PREFIX}).`] };
}
