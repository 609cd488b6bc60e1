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

export const CLASS_FILE_KIND = 'fresnel-lab-class';
export const CLASS_FILE_VERSION = 1;
const FIELDS = ['kind', 'version', 'saved', 'sheet', 'handIns'];
const MAX_SOURCE = 1000;

/**
 * @typedef {{ source: string, data: unknown }} HandIn
 * @typedef {{ source: string, reason: string }} Refusal
 */

const plainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const own = (object, key) => (Object.hasOwn(object, key) ? object[key] : undefined);

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
 * @param {string | Uint8Array} input
 * @param {Partial<typeof import('./classCaps.js').CLASS_CAPS>} [capsGiven]
 * @returns {{ ok: true, sheet: any, saved: string | null, handIns: HandIn[], refused: Refusal[] } | { ok: false, problems: string[] }}
 */
export function readClassFile(input, capsGiven = {}) {
  const caps = classCaps(capsGiven);
  const size = typeof input === 'string' ? input.length : input instanceof Uint8Array ? input.length : -1;
  if (size < 0) return { ok: false, problems: ['A class view is a file of text (JSON).'] };
  if (size > caps.maxClassFileBytes) return { ok: false, problems: [`This file is ${megabytes(size)}: `
    + `more than the ${megabytes(caps.maxClassFileBytes)} a class view may have.`] };
  let doc;
  try {
    doc = JSON.parse(typeof input === 'string' ? input : new TextDecoder().decode(input));
  } catch {
    return { ok: false, problems: ['This file is not readable JSON, so it is no saved class view.'] };
  }
  if (!plainObject(doc) || own(doc, 'kind') !== CLASS_FILE_KIND) {
    return { ok: false, problems: [`This is no saved class view (its kind is not ${CLASS_FILE_KIND}).`] };
  }
  const problems = [];
  if (own(doc, 'version') !== CLASS_FILE_VERSION) problems.push(`version must be ${CLASS_FILE_VERSION}; `
    + `this file says ${rawText(own(doc, 'version'))}.`);
  const sheet = readSheet(own(doc, 'sheet'));
  if (!sheet.ok) problems.push(...sheet.problems.map((p) => `its sheet: ${p}`));
  const handIns = own(doc, 'handIns');
  if (!Array.isArray(handIns)) problems.push('handIns must be a list of hand-ins.');
  if (problems.length) return { ok: false, problems: problems.map((p) => `This class view cannot be opened: ${p}`) };

  /** @type {Refusal[]} */
  const refused = Object.keys(doc).filter((key) => !FIELDS.includes(key))
    .map((key) => ({ source: 'class view', reason: `“${rawText(key, 32)}” is not a field of a class view `
      + `(${FIELDS.join(', ')}); ignored.` }));
  /** @type {HandIn[]} */
  const kept = [];
  handIns.forEach((entry, i) => {
    const label = `hand-in ${i + 1} of the class view`;
    if (i >= caps.maxHandIns) {
      if (i === caps.maxHandIns) refused.push({ source: `hand-ins ${i + 1}–${handIns.length} of the class view`, reason: `not read: `
        + `more than the ${caps.maxHandIns} hand-ins read in all.` });
      return;
    }
    if (!plainObject(entry)) {
      refused.push({ source: label, reason: 'each hand-in is an object { source, data }.' });
      return;
    }
    const source = own(entry, 'source');
    if (!Object.hasOwn(entry, 'data')) refused.push({ source: label, reason: 'it has no data.' });
    else if (typeof source !== 'string' || !source || source.length > MAX_SOURCE) refused.push({ source: label, reason: `its source must `
      + `be a text of 1 to ${MAX_SOURCE} characters.` });
    else kept.push({ source, data: entry.data });
  });
  const saved = own(doc, 'saved');
  const when = typeof saved === 'string' && !Number.isNaN(Date.parse(saved)) ? saved.slice(0, 40) : null;
  return { ok: true, sheet: sheet.sheet, saved: when, handIns: kept, refused };
}
