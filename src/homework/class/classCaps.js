// @ts-check
// How much of what a lecturer brings is read: a class's files come from an LMS, and a zip inside it
// may be a student's (an LMS stores an uploaded zip as it came), so nothing in them is trusted to be
// small. Each cap refuses by name what passes it; none drops anything silently.

import { fixed } from '../../ui/format.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const t = messages('class', english);

const MB = 1024 * 1024;

/** A size in words for a refusal: megabytes, two decimals below one. */
export const megabytes = (/** @type {number} */ bytes) => t('megabytes', { size: fixed(bytes / MB, bytes < MB ? 2 : 1) });

export const CLASS_CAPS = Object.freeze({
  /** A .json or .txt file, picked or unpacked: a hand-in is a few kilobytes (40 questions: about 3 KB);
   * a .txt of a whole class's codes (500 of them) is about 1.5 MB. */
  maxFileBytes: 4 * MB,
  /** A zip that was picked or dropped: an LMS's download may hold PDFs and images too, which are
   * refused by name from the zip's directory without being unpacked, so it may be large. */
  maxZipBytes: 200 * MB,
  /** A zip inside a zip, unpacked: a student's own zip holds one hand-in. */
  maxNestedZipBytes: 20 * MB,
  /** Entries in one zip's directory (a zip with more is refused before anything is unpacked), and
   * files unpacked from all zips together. */
  maxEntries: 2000,
  /** Bytes unpacked from all zips together; each entry is also held to the size its kind may have. */
  maxUnpackedBytes: 50 * MB,
  /** A zip in a zip in a zip: deeper ones are refused by name. */
  maxDepth: 3,
  /** Pasted text, in characters (as large as a .txt may be). */
  maxTextChars: 4 * MB,
  /** Hand-ins read in all: far above a class, low enough that grading stays seconds. */
  maxHandIns: 2000,
  /** A saved class view (classFile.js): the sheet and every hand-in's data. */
  maxClassFileBytes: 50 * MB,
});

/** @typedef {{ -readonly [K in keyof typeof CLASS_CAPS]: number }} ClassCaps */

/**
 * The caps, with any of them replaced (tests use small ones); a replacement that is not a positive number is ignored.
 * @param {Partial<ClassCaps> | null} [overrides]
 * @returns {ClassCaps}
 */
export function classCaps(overrides = {}) {
  /** @type {ClassCaps} */
  const caps = { ...CLASS_CAPS };
  for (const key of /** @type {(keyof ClassCaps)[]} */ (Object.keys(CLASS_CAPS))) {
    const value = overrides && Object.hasOwn(overrides, key) ? overrides[key] : undefined;
    if (typeof value === 'number' && value > 0) caps[key] = value;
  }
  return caps;
}
