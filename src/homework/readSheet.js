// @ts-check
// A homework sheet (what a lecturer composes), read from untrusted JSON: every field is checked
// and anything unexpected is refused with a reason. Handed-in files: gradeHandIn.js. A sheet may
// carry the language it was made in (`lang`: one of src/i18n/languages.js), so that it opens in it.
import { questionById } from './questions.js';
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { clipText, rawText, resolveKey } from '../host/params.js';
import { isObject, own } from '../host/own.js';
import { panelSchema } from '../panels/panelSchema.js';
import { LANGUAGES, languageById } from '../i18n/languages.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

export const SHEET_VERSION = 1;
const MAX_ITEMS = 40;
const MAX_STATE_KEYS = 24;
/** @type {(v: unknown, max: number) => v is string} */
const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;
const SHEET_FIELDS = ['version', 'title', 'reveal', 'seed', 'lang', 'items'];
const ITEM_FIELDS = ['question', 'state'];

const t = messages('homework', english);

/** @typedef {import('../homework/questionParts.js').PanelState} PanelState */
/** @typedef {{ question: string, state?: PanelState }} SheetItem  a question of the sheet, and where its panel starts */
/**
 * A sheet as readSheet gives it: every field checked, reveal filled in.
 * @typedef {{ version: number, title: string, reveal: 'after-answer' | 'lecturer', seed?: string, lang?: string,
 *   items: SheetItem[] }} Sheet
 */
/**
 * A sheet read, or refused with the reasons. (The other member's field is there, undefined, so
 * that the loose project, which cannot narrow on `ok`, reads both.)
 * @typedef {{ ok: true, sheet: Sheet, problems?: undefined } | { ok: false, problems: string[], sheet?: undefined }} ReadSheet
 */

/**
 * Fields a sheet or an item (item: its number) does not have, named: a typo such as "stat" would lose the start state unseen.
 * @param {object} object
 * @param {string[]} fields
 * @param {number | null} [item]
 */
const unknownFields = (object, fields, item = null) => Object.keys(object).filter((key) => !fields.includes(key))
  .map((key) => {
    const named = { field: rawText(key, 32), fields: fields.join(', ') };
    return item === null ? t('sheet.unknownField', named) : t('sheet.unknownItemField', { ...named, item });
  });

/** Whether a sheet's `lang` is a language of the lab (a listed one, or a pseudo-locale the tests ask for). */
export const sheetLanguage = (/** @type {unknown} */ lang) => typeof lang === 'string' && languageById(lang) !== undefined;

/**
 * An item's start state: panel values the question does not set (a view, a roughness). Its shape
 * and its names are checked here (a name the panel does not know would be dropped there without a
 * word); the panel checks each value against its schema and says so on screen.
 * Returns the problems, and the state (a copy) where there are none.
 * @param {unknown} state
 * @param {string} panelId
 * @param {number} item
 * @returns {{ problems: string[], state?: PanelState }}
 */
function readState(state, panelId, item) {
  if (state === undefined) return { problems: [] };
  if (!isObject(state)) return { problems: [t('sheet.stateNotObject', { item })] };
  const entries = Object.entries(state);
  if (entries.length > MAX_STATE_KEYS) return { problems: [t('sheet.stateTooLarge', { item, max: MAX_STATE_KEYS })] };
  /** @type {PanelState} */
  const kept = {};
  const problems = entries.flatMap(([key, value]) => {
    if (!/^[A-Za-z][A-Za-z0-9]{0,31}$/.test(key)) return [t('sheet.stateBadName', { item, key: clipText(key, 32) })];
    // The frame's own options (which panel, locks, the deck's origin) are the sheet page's to set.
    if (EMBED_KEYS.includes(key)) return [t('sheet.stateEmbedOption', { item, key })];
    if (resolveKey(panelSchema(panelId) ?? {}, key) === undefined) return [t('sheet.stateUnknown', { item, key })];
    const fits = (typeof value === 'number' && Number.isFinite(value)) || typeof value === 'boolean' || text(value, 64);
    if (!fits) return [t('sheet.stateValue', { item, key })];
    kept[key] = value;
    return [];
  });
  return problems.length ? { problems } : { problems, state: kept };
}

/**
 * { ok: true, sheet } with the sheet's items normalised, or { ok: false, problems: [text] }.
 * @param {unknown} data
 * @returns {ReadSheet}
 */
export function readSheet(data) {
  /** @type {string[]} */
  const problems = [];
  if (!isObject(data)) return { ok: false, problems: [t('sheet.notObject')] };
  const field = (/** @type {string} */ key) => own(data, key);
  problems.push(...unknownFields(data, SHEET_FIELDS));
  if (field('version') !== SHEET_VERSION) problems.push(t('sheet.version', { version: SHEET_VERSION }));
  const rawTitle = field('title');
  const title = text(rawTitle, 200) ? rawTitle : null;
  if (title === null) problems.push(t('sheet.title'));
  const rawItems = field('items');
  /** @type {SheetItem[]} */
  const items = [];
  if (!Array.isArray(rawItems) || rawItems.length === 0 || rawItems.length > MAX_ITEMS) {
    problems.push(t('sheet.items', { max: MAX_ITEMS }));
  } else {
    rawItems.forEach((/** @type {unknown} */ item, i) => {
      const fields = isObject(item) ? item : null;
      if (fields) problems.push(...unknownFields(fields, ITEM_FIELDS, i + 1));
      const id = fields ? own(fields, 'question') : undefined;
      const question = questionById(id);
      // rawText: the id may be any JSON, and String() of an object whose toString is not a function throws.
      if (!fields || !question) {
        problems.push(t('sheet.noQuestion', { item: i + 1, id: rawText(id) }));
        return;
      }
      const read = readState(own(fields, 'state'), question.panel, i + 1);
      problems.push(...read.problems);
      items.push({ question: question.id, ...(read.state ? { state: read.state } : {}) });
    });
  }
  // Each optional field may be absent; one that is there and cannot be used is said.
  const seed = field('seed');
  if (seed !== undefined && !text(seed, 64)) problems.push(t('sheet.seed'));
  const rawReveal = field('reveal');
  const reveal = rawReveal === undefined ? 'after-answer'
    : rawReveal === 'after-answer' ? 'after-answer' : rawReveal === 'lecturer' ? 'lecturer' : null;
  if (reveal === null) problems.push(t('sheet.reveal'));
  const lang = field('lang');
  if (lang !== undefined && !sheetLanguage(lang)) {
    problems.push(t('sheet.lang', { languages: LANGUAGES.map((l) => l.id).join(', '), lang: rawText(lang, 32) }));
  }
  if (problems.length || title === null || reveal === null) return { ok: false, problems };
  // Past the problems, a seed or a language that is there is text that passed its check.
  return {
    ok: true,
    sheet: {
      version: SHEET_VERSION,
      title,
      reveal,
      ...(typeof seed === 'string' ? { seed } : {}),
      ...(typeof lang === 'string' ? { lang } : {}),
      items,
    },
  };
}
