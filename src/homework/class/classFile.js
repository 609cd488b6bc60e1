// @ts-check
// A class view saved as a file, to open again later or on another machine: the sheet that was set,
// and every hand-in's data with where it came from. No grade is stored: opening the file grades
// every hand-in again (gradeClass.js), so an edited file can change what is graded, never a grade.
// The file is read as untrusted input: caps on its size and counts, own keys only (a key such as
// constructor or __proto__ finds nothing inherited), and every part that cannot be used refused by
// name while the rest is kept.
import { classCaps, megabytes } from './classCaps.js';
import { readSheet } from '../readSheet.js';
import { rawText } from '../../host/params.js';
import { isObject, own } from '../../host/own.js';
import english from 'virtual:messages/en/class';
import { messages } from '../../i18n/messages.js';

const t = messages('class', english);

export const CLASS_FILE_KIND = 'fresnel-lab-class';
export const CLASS_FILE_VERSION = 1;
const FIELDS = ['kind', 'version', 'saved', 'sheet', 'handIns'];
const MAX_SOURCE = 1000;

/**
 * @typedef {{ source: string, data: unknown }} HandIn
 * @typedef {{ source: string, reason: string }} Refusal
 */

/**
 * The file's text (JSON): { kind, version, saved, sheet, handIns: [{ source, data }] }.
 * @param {{ sheet: unknown, handIns: HandIn[], saved?: string }} view
 * @returns {string}
 */
export function writeClassFile({ sheet, handIns, saved = new Date().toISOString() }) {
  const list = handIns.map(({ source, data }) => ({ source, data }));
  return JSON.stringify({ kind: CLASS_FILE_KIND, version: CLASS_FILE_VERSION, saved, sheet, handIns: list });
}

/**
 * Reads a saved class view (its text or bytes): { ok: true, sheet, saved, handIns, refused } to be
 * graded again by gradeClass, or { ok: false, problems } when it is no class view or its sheet
 * cannot be read. Never throws on any input.
 * @param {unknown} input  its text or bytes (anything else is refused)
 * @param {Partial<import('./classCaps.js').ClassCaps>} [capsGiven]
 * @returns {{ ok: true, sheet: import('../readSheet.js').Sheet, saved: string | null, handIns: HandIn[], refused: Refusal[],
 *   problems?: undefined } | { ok: false, problems: string[] }}
 */
export function readClassFile(input, capsGiven = {}) {
  const caps = classCaps(capsGiven);
  if (typeof input !== 'string' && !(input instanceof Uint8Array)) return { ok: false, problems: [t('classFile.notText')] };
  const size = input.length;
  if (size > caps.maxClassFileBytes) {
    return { ok: false, problems: [t('classFile.tooLarge', { size: megabytes(size), max: megabytes(caps.maxClassFileBytes) })] };
  }
  /** @type {unknown} */
  let doc;
  try {
    doc = JSON.parse(typeof input === 'string' ? input : new TextDecoder().decode(input));
  } catch {
    return { ok: false, problems: [t('classFile.notJson')] };
  }
  if (!isObject(doc) || own(doc, 'kind') !== CLASS_FILE_KIND) {
    return { ok: false, problems: [t('classFile.otherKind', { kind: CLASS_FILE_KIND })] };
  }
  /** @type {string[]} */
  const problems = [];
  if (own(doc, 'version') !== CLASS_FILE_VERSION) {
    problems.push(t('classFile.version', { version: CLASS_FILE_VERSION, found: rawText(own(doc, 'version')) }));
  }
  const sheet = readSheet(own(doc, 'sheet'));
  if (!sheet.ok) problems.push(...sheet.problems.map((problem) => t('classFile.sheet', { problem })));
  const handIns = own(doc, 'handIns');
  if (!Array.isArray(handIns)) problems.push(t('classFile.handIns'));
  if (problems.length || !sheet.ok || !Array.isArray(handIns)) {
    return { ok: false, problems: problems.map((problem) => t('classFile.cannotOpen', { problem })) };
  }

  /** @type {Refusal[]} */
  const refused = Object.keys(doc).filter((key) => !FIELDS.includes(key))
    .map((key) => ({
      source: t('source.classView'), reason: t('classFile.unknownField', { field: rawText(key, 32), fields: FIELDS.join(', ') }),
    }));
  /** @type {HandIn[]} */
  const kept = [];
  handIns.forEach((/** @type {unknown} */ entry, i) => {
    const label = t('source.classViewHandIn', { number: i + 1 });
    if (i >= caps.maxHandIns) {
      if (i === caps.maxHandIns) {
        const source = t('source.classViewRest', { from: i + 1, to: handIns.length });
        refused.push({ source, reason: t('classFile.overCap', { max: caps.maxHandIns }) });
      }
      return;
    }
    if (!isObject(entry)) {
      refused.push({ source: label, reason: t('classFile.notEntry') });
      return;
    }
    const source = own(entry, 'source');
    if (!Object.hasOwn(entry, 'data')) refused.push({ source: label, reason: t('classFile.noData') });
    else if (typeof source !== 'string' || !source || source.length > MAX_SOURCE) {
      refused.push({ source: label, reason: t('classFile.source', { max: MAX_SOURCE }) });
    }
    else kept.push({ source, data: own(entry, 'data') });
  });
  const saved = own(doc, 'saved');
  const when = typeof saved === 'string' && !Number.isNaN(Date.parse(saved)) ? saved.slice(0, 40) : null;
  return { ok: true, sheet: sheet.sheet, saved: when, handIns: kept, refused };
}
