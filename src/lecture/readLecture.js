// @ts-check
// A lecture as data: a title and a list of items, each a panel (its id, where it starts, controls
// locked or hidden as an embed link has them, a heading and text of the lecturer's own), a text
// item (an agenda, a reference list), or a question from the homework bank asked of the room.
// A lecture comes from anyone (a link, a file), so it is read as untrusted data: own keys only,
// sizes capped, every value checked against the panel's schema, and whatever cannot be used is
// named while the rest of the lecture is kept. It may carry the language it was written in (lang),
// one the lab speaks (src/i18n/languages.js), so that it opens in that language.
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';
import { LANGUAGES, languageById } from '../i18n/languages.js';
import { fixed } from '../ui/format.js';
import { applyParams, defaults, describeProblem, rawText, resolveKey } from '../host/params.js';
import { isObject, own } from '../host/own.js';
import { panelEntry } from '../panels/manifest.js';
import { panelSchema } from '../panels/panelSchema.js';
import { questionById } from '../homework/questions.js';

const t = messages('lecture', english);

export const LECTURE_KIND = 'fresnel-lab-lecture';
export const LECTURE_VERSION = 1;
/** The seed of a question item that names none: the same numbers on the page, in the deck and in the composer. */
export const ROOM_SEED = 'lecture';

export const LECTURE_CAPS = Object.freeze({ items: 80, title: 200, heading: 200, text: 4000, keys: 64, seed: 64 });
/** @typedef {import('../host/panelContract.js').Value} ParamValue */
/** @typedef {{ heading?: string, text?: string }} OwnText  the lecturer's own heading and text (Markdown) */
/**
 * A panel where it starts (the values that differ from its defaults) and the controls a deck's
 * link would lock or hide.
 * @typedef {OwnText & { type: 'panel', panel: string, state?: Record<string, ParamValue>, lock?: string[], hide?: string[] }} PanelItem
 */
/** @typedef {OwnText & { type: 'text' }} TextItem */
/** @typedef {OwnText & { type: 'question', question: string, seed?: string }} QuestionItem  seed: ROOM_SEED where absent */
/** @typedef {PanelItem | TextItem | QuestionItem} LectureItem */
/** @typedef {{ kind: string, version: number, title: string, lang?: string, items: LectureItem[] }} Lecture */
/**
 * A lecture read, or refused whole. (The other member's field is there, undefined, so that the
 * loose project, which cannot narrow on `ok`, reads both.)
 * @typedef {{ ok: true, lecture: Lecture, problems: string[] } | { ok: false, problems: string[], lecture?: undefined }} ReadLecture
 */

/** @type {Readonly<Record<string, readonly string[]>>} the fields each type of item may have */
const ITEM_FIELDS = {
  panel: ['type', 'panel', 'state', 'lock', 'hide', 'heading', 'text'],
  text: ['type', 'heading', 'text'],
  question: ['type', 'question', 'seed', 'heading', 'text'],
};

/** @typedef {{ field: string, where?: string }} What  which text, as the messages name it */

/**
 * An optional text: undefined when absent, else the text or a problem (not text, too long). what:
 * which text, as the messages name it ({ field, where }: 'title', 'heading', 'text' or 'seed', and
 * the item's place).
 * @param {unknown} value
 * @param {number} max
 * @param {What} what
 * @param {string[]} problems
 */
function optionalText(value, max, what, problems) {
  if (value === undefined) return undefined;
  if (typeof value !== 'string') { problems.push(t('textNotText', what)); return undefined; }
  if (value.length > max) {
    problems.push(t('textTooLong', { ...what, length: fixed(value.length, 0), max: fixed(max, 0) }));
    return undefined;
  }
  return value;
}

/**
 * A list of the panel's control keys (locked or hidden), each resolved to its schema key. what: { where, field }.
 * @param {unknown} value
 * @param {import('../host/panelContract.js').Schema} schema
 * @param {What} what
 * @param {string[]} problems
 */
function keyList(value, schema, what, problems) {
  if (value === undefined) return undefined;
  if (!Array.isArray(value) || value.length > LECTURE_CAPS.keys) {
    problems.push(t('keysNotList', { ...what, max: fixed(LECTURE_CAPS.keys, 0) }));
    return undefined;
  }
  /** @type {string[]} */
  const keys = [];
  for (const name of value) {
    const key = typeof name === 'string' ? resolveKey(schema, name) : undefined;
    if (key === undefined) problems.push(t('keyNotControl', { ...what, name: rawText(name, 40) }));
    else if (!keys.includes(key)) keys.push(key);
  }
  return keys;
}

/**
 * @param {Record<string, unknown>} item
 * @param {string} where
 * @param {string[]} problems
 * @returns {PanelItem | null}
 */
function readPanelItem(item, where, problems) {
  const id = own(item, 'panel');
  const schema = typeof id === 'string' ? panelSchema(id) : undefined;
  if (typeof id !== 'string' || !schema || !panelEntry(id)) {
    problems.push(t('noPanel', { where, id: rawText(id, 40) }));
    return null;
  }
  /** @type {PanelItem} */
  const out = { type: 'panel', panel: id };
  const state = own(item, 'state');
  if (state !== undefined) {
    if (!isObject(state)) problems.push(t('stateNotValues', { where }));
    else {
      // Read as a link is: each value checked by the schema, what is refused named; defaults are not stored.
      const start = defaults(schema);
      const { applied, rejected } = applyParams(schema, { ...start }, Object.fromEntries(Object.keys(state).map((k) => [k, state[k]])));
      for (const r of rejected) problems.push(t('itemProblem', { where, problem: describeProblem(r) }));
      const kept = Object.fromEntries(Object.entries(applied).filter(([k, v]) => !Object.is(v, start[k])));
      if (Object.keys(kept).length) out.state = kept;
    }
  }
  for (const field of /** @type {const} */ (['lock', 'hide'])) {
    const keys = keyList(own(item, field), schema, { where, field }, problems);
    if (keys?.length) out[field] = keys;
  }
  return out;
}

/**
 * @param {Record<string, unknown>} item
 * @param {string} where
 * @param {string[]} problems
 * @returns {QuestionItem | null}
 */
function readQuestionItem(item, where, problems) {
  const id = own(item, 'question');
  if (typeof id !== 'string' || !questionById(id)) {
    problems.push(t('noQuestion', { where, id: rawText(id, 40) }));
    return null;
  }
  /** @type {QuestionItem} */
  const out = { type: 'question', question: id };
  const seed = optionalText(own(item, 'seed'), LECTURE_CAPS.seed, { field: 'seed', where }, problems);
  if (seed !== undefined && seed.trim()) out.seed = seed.trim();
  return out;
}

/**
 * One item, or null (named in problems) when it cannot be used.
 * @param {unknown} item
 * @param {number} i
 * @param {string[]} problems
 * @returns {LectureItem | null}
 */
function readItem(item, i, problems) {
  const where = t('itemPlace', { n: fixed(i + 1, 0) });
  if (!isObject(item)) {
    problems.push(t('notItem', { where }));
    return null;
  }
  const type = own(item, 'type');
  const fields = typeof type === 'string' && Object.hasOwn(ITEM_FIELDS, type) ? ITEM_FIELDS[type] : null;
  if (!fields) {
    problems.push(t('noKind', { where, type: rawText(type, 40) }));
    return null;
  }
  for (const key of Object.keys(item)) {
    if (!fields.includes(key)) problems.push(t('noItemField', { where, key: rawText(key, 40), type }));
  }
  /** @type {LectureItem | null} */
  const out = type === 'panel' ? readPanelItem(item, where, problems)
    : type === 'question' ? readQuestionItem(item, where, problems)
    : { type: 'text' };
  if (!out) return null;
  const heading = optionalText(own(item, 'heading'), LECTURE_CAPS.heading, { field: 'heading', where }, problems);
  const text = optionalText(own(item, 'text'), LECTURE_CAPS.text, { field: 'text', where }, problems);
  if (heading?.trim()) out.heading = heading.trim();
  if (text?.trim()) out.text = text.trim();
  if (type === 'text' && !out.text && !out.heading) {
    problems.push(t('emptyText', { where }));
    return null;
  }
  return out;
}

/**
 * The lecture's language: an id of src/i18n/languages.js, else undefined (and what was refused, named).
 * @param {unknown} value
 * @param {string[]} problems
 */
function readLanguage(value, problems) {
  if (value === undefined) return undefined;
  if (typeof value === 'string' && languageById(value)) return value;
  problems.push(t('noLanguage', { lang: rawText(value, 20), languages: LANGUAGES.map((l) => l.id).join(', ') }));
  return undefined;
}

/**
 * { ok: true, lecture: { kind, version, title, lang?, items }, problems } — the lecture as far as it can
 * be used, each part left out named in problems — or { ok: false, problems } when the data is no
 * lecture at all. Never throws.
 * @param {unknown} data
 * @returns {ReadLecture}
 */
export function readLecture(data) {
  if (!isObject(data)) return { ok: false, problems: [t('notObject')] };
  if (own(data, 'kind') !== LECTURE_KIND) {
    return { ok: false, problems: [t('notLecture', { kind: rawText(own(data, 'kind'), 40), expected: LECTURE_KIND })] };
  }
  if (own(data, 'version') !== LECTURE_VERSION) {
    return { ok: false, problems: [t('otherVersion', { version: rawText(own(data, 'version'), 20), reads: `${LECTURE_VERSION}` })] };
  }
  /** @type {string[]} */
  const problems = [];
  for (const key of Object.keys(data)) {
    if (!['kind', 'version', 'title', 'lang', 'items'].includes(key)) problems.push(t('noLectureField', { key: rawText(key, 40) }));
  }
  const title = optionalText(own(data, 'title'), LECTURE_CAPS.title, { field: 'title' }, problems)?.trim() || t('untitled');
  const lang = readLanguage(own(data, 'lang'), problems);
  const raw = own(data, 'items');
  if (!Array.isArray(raw)) return { ok: false, problems: [t('noItems')] };
  if (raw.length > LECTURE_CAPS.items) {
    problems.push(t('tooManyItems', { count: fixed(raw.length, 0), max: fixed(LECTURE_CAPS.items, 0) }));
  }
  /** @type {LectureItem[]} */
  const items = [];
  raw.slice(0, LECTURE_CAPS.items).forEach((/** @type {unknown} */ item, i) => {
    const read = readItem(item, i, problems);
    if (read) items.push(read);
  });
  const lecture = { kind: LECTURE_KIND, version: LECTURE_VERSION, title, ...(lang ? { lang } : {}), items };
  return { ok: true, lecture, problems };
}
