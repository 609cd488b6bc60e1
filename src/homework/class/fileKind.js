// @ts-check
// Which files of a class are read, by name: a handed-in file (.json), text that holds codes (.txt),
// an HTML page that holds them (.html, .htm: an LMS's "online text", the box where students paste
// their code), and zips (.zip) whose files are read the same way. A file with no extension at all
// ("handin", as a Mac may save it) is read for what its first bytes say it is (contentKind).
// Anything else is refused with its name, from a zip's directory before it is unpacked, so an LMS
// download with PDFs and photos costs nothing.

import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

/** @typedef {'json' | 'text' | 'html' | 'zip' | 'by-content'} FileKind */

const t = messages('class', english);

/** The last part of a path (a file in a zip or a dropped folder). */
export const baseName = (/** @type {string} */ path) => path.slice(path.lastIndexOf('/') + 1);

/** @type {Readonly<Record<string, FileKind>>} */
const EXTENSIONS = { json: 'json', txt: 'text', html: 'html', htm: 'html', zip: 'zip' };

/**
 * { kind } for a file that is read, or { reason } why it is not.
 * @param {string} path
 * @returns {{ kind: FileKind, reason?: undefined } | { kind?: undefined, reason: string }}
 */
export function fileKind(path) {
  const name = baseName(path);
  // A Mac's zip tool adds a resource-fork twin (__MACOSX/…/._handin.json) for every file: binary, no hand-in.
  if (path.split('/').includes('__MACOSX') || name.startsWith('._')) return { reason: t('file.macMetadata') };
  const dot = name.lastIndexOf('.');
  if (dot <= 0) return { kind: 'by-content' };
  const extension = name.slice(dot + 1).toLowerCase();
  if (Object.hasOwn(EXTENSIONS, extension)) return { kind: EXTENSIONS[extension] };
  return { reason: t('file.otherKind', { extension: extension.slice(0, 12) }) };
}

const startsWith = (/** @type {Uint8Array} */ bytes, /** @type {number[]} */ ...values) => values.every((v, i) => bytes[i] === v);

/**
 * What a file without an extension holds, from its bytes: { kind: 'zip' | 'text' } (text covers a
 * handed-in file's JSON, codes and HTML alike: the text reader tells them apart), or { reason }.
 * @param {Uint8Array} bytes
 * @returns {{ kind: 'zip' | 'text', reason?: undefined } | { kind?: undefined, reason: string }}
 */
export function contentKind(bytes) {
  if (startsWith(bytes, 0x50, 0x4b, 0x03, 0x04) || startsWith(bytes, 0x50, 0x4b, 0x05, 0x06)) return { kind: 'zip' };
  if (startsWith(bytes, 0x25, 0x50, 0x44, 0x46)) return { reason: t('file.pdf') };
  // UTF-16 text has a zero in every other byte; its byte-order mark says so. Any other zero early on is a binary file.
  const utf16 = startsWith(bytes, 0xff, 0xfe) || startsWith(bytes, 0xfe, 0xff);
  if (!utf16 && bytes.subarray(0, 1024).includes(0)) return { reason: t('file.binary') };
  return { kind: 'text' };
}
