// @ts-check
// A class's hand-ins from what a lecturer brings: files picked or a folder dropped (handed-in .json
// files, .txt files of codes, .html pages of an LMS's online text, files without an extension read
// for what they hold, an LMS's zip of everyone's submissions, zips inside it), and text pasted
// (codes and handed-in files' JSON, among other text). Each hand-in keeps where it came from
// (an LMS's folder often names the student: lmsName.js); everything that is not read is refused
// with its name and the reason. Reading only finds data: gradeClass.js decides what it is.
import { classCaps, megabytes } from './classCaps.js';
import { contentKind, fileKind } from './fileKind.js';
import { findHandIns } from './findHandIns.js';
import { htmlToText, looksLikeHtml } from './htmlText.js';
import { unzipBounded } from './unzipBounded.js';
import { own } from '../../host/own.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/**
 * @typedef {{ source: string, data: unknown }} HandIn
 * @typedef {{ source: string, reason: string }} Refusal
 * @typedef {{ name: string, bytes: Uint8Array | ArrayBuffer }} PickedFile
 */

const t = messages('class', english);

/**
 * Text from a file's bytes: UTF-8 (a byte-order mark dropped), or UTF-16 where its mark says so (Windows' "Unicode").
 * @param {Uint8Array} bytes
 */
export function decodeText(bytes) {
  if (bytes[0] === 0xff && bytes[1] === 0xfe) return new TextDecoder('utf-16le').decode(bytes.subarray(2));
  if (bytes[0] === 0xfe && bytes[1] === 0xff) return new TextDecoder('utf-16be').decode(bytes.subarray(2));
  // Not fatal: codes are ASCII, so a stray byte elsewhere in a mail or a CSV export costs nothing.
  return new TextDecoder('utf-8').decode(bytes); // drops a UTF-8 byte-order mark
}

/**
 * Reads files and text into hand-ins. files: [{ name (its path), bytes }]; text: pasted text;
 * caps: any of CLASS_CAPS replaced. Never throws on any input (a worker passes on what it was sent).
 * @param {{ files?: unknown, text?: unknown }} [input]
 * @param {Partial<import('./classCaps.js').ClassCaps>} [capsGiven]
 * @returns {{ handIns: HandIn[], refused: Refusal[] }}
 */
export function readClassHandIns({ files = [], text = '' } = {}, capsGiven = {}) {
  const caps = classCaps(capsGiven);
  /** @type {HandIn[]} */
  const handIns = [];
  /** @type {Refusal[]} */
  const refused = [];
  const budget = { entries: caps.maxEntries, bytes: caps.maxUnpackedBytes };
  const left = () => caps.maxHandIns - handIns.length;

  /** @type {(content: string, source: string) => void} */
  const readText = (content, source) => {
    const found = findHandIns(content, source, { maxHandIns: Math.max(0, left()) });
    handIns.push(...found.handIns);
    refused.push(...found.refused);
  };

  /** @type {(kind: string, size: number, max: number) => string} */
  const tooLarge = (kind, size, max) => t('file.tooLarge', { kind, size: megabytes(size), max: megabytes(max) });

  /**
   * A zip entry's size is decided from its directory, before it is unpacked.
   * @type {(path: string, claimed: number) => string | null}
   */
  const admit = (path, claimed) => {
    const kind = fileKind(path);
    if (kind.reason) return kind.reason;
    // A file without an extension may be a zip: held to a zip's cap here, and to a file's once its bytes say it is text.
    const max = kind.kind === 'zip' || kind.kind === 'by-content' ? caps.maxNestedZipBytes : caps.maxFileBytes;
    if (claimed <= max) return null;
    return t('file.unpacksTooLarge', { kind: kind.kind === 'zip' ? 'zip' : 'file', size: megabytes(claimed), max: megabytes(max) });
  };

  /**
   * A text file's content: an HTML page's text (tags dropped, entities decoded), any other as it is.
   * @type {(name: string, bytes: Uint8Array, html: boolean) => void}
   */
  const readTextFile = (name, bytes, html) => {
    if (bytes.length > caps.maxFileBytes) {
      refused.push({ source: name, reason: tooLarge('file', bytes.length, caps.maxFileBytes) });
      return;
    }
    const decoded = decodeText(bytes);
    const content = html || looksLikeHtml(decoded) ? htmlToText(decoded) : decoded;
    if (content.trim()) readText(content, name);
    else refused.push({ source: name, reason: html && decoded.trim() ? t('file.emptyHtml') : t('file.empty') });
  };

  /** @type {(name: string, bytes: Uint8Array, depth: number) => void} */
  const readFile = (name, bytes, depth) => {
    const named = fileKind(name);
    const kind = named.kind === 'by-content' ? contentKind(bytes) : named;
    if (kind.reason) {
      refused.push({ source: name, reason: kind.reason });
    } else if (kind.kind === 'zip') {
      const max = depth === 0 ? caps.maxZipBytes : caps.maxNestedZipBytes;
      if (depth >= caps.maxDepth) refused.push({ source: name, reason: t('zip.tooDeep', { depth, max: caps.maxDepth }) });
      else if (bytes.length > max) refused.push({ source: name, reason: tooLarge('zip', bytes.length, max) });
      else {
        const zip = unzipBounded(bytes, { name, admit, budget, maxEntries: caps.maxEntries });
        refused.push(...zip.refused);
        for (const file of zip.files) readFile(file.name, file.bytes, depth + 1);
        if (!zip.files.length && !zip.refused.length) refused.push({ source: name, reason: t('zip.empty') });
      }
    } else readTextFile(name, bytes, kind.kind === 'html'); // a text that starts as an HTML page is read as one too
  };

  /** @type {unknown[]} */
  const list = Array.isArray(files) ? files : [];
  // A file's name and bytes, read as own properties of whatever was given (a PickedFile, or nothing of the kind).
  list.forEach((file, i) => {
    const given = own(file, 'name');
    const name = typeof given === 'string' && given ? given : t('source.file', { number: i + 1 });
    const content = own(file, 'bytes');
    const bytes = content instanceof Uint8Array ? content : content instanceof ArrayBuffer ? new Uint8Array(content) : null;
    try {
      if (!bytes) refused.push({ source: name, reason: t('file.noContent') });
      else readFile(name, bytes, 0);
    } catch (error) {
      // Not expected (every reader refuses by name); if it happens, the file is still named.
      refused.push({ source: name, reason: t('file.error', { error: error instanceof Error ? error.message : t('anError') }) });
    }
  });

  if (typeof text === 'string' && text.trim()) {
    if (text.length > caps.maxTextChars) {
      refused.push({ source: t('source.pasted'), reason: t('text.tooLong', { length: text.length, max: caps.maxTextChars }) });
    }
    else readText(text, t('source.pasted'));
  }
  return { handIns, refused };
}
