// A homework sheet (what a lecturer composes), read from untrusted JSON: every field is checked
// and anything unexpected is refused with a reason. Handed-in files: gradeHandIn.js. A sheet may
// carry the language it was made in (`lang`: one of src/i18n/languages.js), so that it opens in it.
import { questionById } from './questions.js';
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { clipText, rawText, resolveKey } from '../host/params.js';
import { isObject } from '../host/own.js';
import { panelSchema } from '../panels/panelSchema.js';
import { LANGUAGES, languageById } from '../i18n/languages.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

export const SHEET_VERSION = 1;
const MAX_ITEMS = 40;
const MAX_STATE_KEYS = 24;
const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;
const SHEET_FIELDS = ['version', 'title', 'reveal', 'seed', 'lang', 'items'];
const ITEM_FIELDS = ['question', 'state'];

const t = messages('homework', english);

/** Fields a sheet or an item (item: its number) does not have, named: a typo such as "stat" would lose the start state unseen. */
const unknownFields = (object, fields, item = null) => Object.keys(object).filter((key) => !fields.includes(key))
  .map((key) => {
    const named = { field: rawText(key, 32), fields: fields.join(', ') };
    return item === null ? t('sheet.unknownField', named) : t('sheet.unknownItemField', { ...named, item });
  });

/** Whether a sheet's `lang` is a language of the lab (a listed one, or a pseudo-locale the tests ask for). */
export const sheetLanguage = (lang) => typeof lang === 'string' && languageById(lang) !== undefined;

/**
 * An item's start state: panel values the question does not set (a view, a roughness). Its shape
 * and its names are checked here (a name the panel does not know would be dropped there without a
 * word); the panel checks each value against its schema and says so on screen.
 */
function stateProblems(state, panelId, item) {
  if (state === undefined) return [];
  if (!isObject(state)) return [t('sheet.stateNotObject', { item })];
  const entries = Object.entries(state);
  if (entries.length > MAX_STATE_KEYS) return [t('sheet.stateTooLarge', { item, max: MAX_STATE_KEYS })];
  return entries.flatMap(([key, value]) => {
    if (!/^[A-Za-z][A-Za-z0-9]{0,31}$/.test(key)) return [t('sheet.stateBadName', { item, key: clipText(key, 32) })];
    // The frame's own options (which panel, locks, the deck's origin) are the sheet page's to set.
    if (EMBED_KEYS.includes(key)) return [t('sheet.stateEmbedOption', { item, key })];
    if (resolveKey(panelSchema(panelId) ?? {}, key) === undefined) return [t('sheet.stateUnknown', { item, key })];
    const fits = (typeof value === 'number' && Number.isFinite(value)) || typeof value === 'boolean' || text(value, 64);
    return fits ? [] : [t('sheet.stateValue', { item, key })];
  });
}

/** { ok: true, sheet } with the sheet's items normalised, or { ok: false, problems: [text] }. */
export function readSheet(data) {
  const problems = [];
  if (!data || typeof data !== 'object' || Array.isArray(data)) return { ok: false, problems: [t('sheet.notObject')] };
  problems.push(...unknownFields(data, SHEET_FIELDS));
  if (data.version !== SHEET_VERSION) problems.push(t('sheet.version', { version: SHEET_VERSION }));
  if (!text(data.title, 200)) problems.push(t('sheet.title'));
  if (!Array.isArray(data.items) || data.items.length === 0 || data.items.length > MAX_ITEMS) {
    problems.push(t('sheet.items', { max: MAX_ITEMS }));
  } else {
    data.items.forEach((item, i) => {
      if (isObject(item)) problems.push(...unknownFields(item, ITEM_FIELDS, i + 1));
      const question = questionById(item?.question);
      // rawText: the id may be any JSON, and String() of an object whose toString is not a function throws.
      if (!question) problems.push(t('sheet.noQuestion', { item: i + 1, id: rawText(item?.question) }));
      else problems.push(...stateProblems(item.state, question.panel, i + 1));
    });
  }
  if (data.seed !== undefined && !text(data.seed, 64)) problems.push(t('sheet.seed'));
  if (data.reveal !== undefined && !['after-answer', 'lecturer'].includes(data.reveal)) problems.push(t('sheet.reveal'));
  if (data.lang !== undefined && !sheetLanguage(data.lang)) {
    problems.push(t('sheet.lang', { languages: LANGUAGES.map((l) => l.id).join(', '), lang: rawText(data.lang, 32) }));
  }
  if (problems.length) return { ok: false, problems };
  return {
    ok: true,
    sheet: {
      version: SHEET_VERSION,
      title: data.title,
      reveal: data.reveal ?? 'after-answer',
      ...(data.seed === undefined ? {} : { seed: data.seed }),
      ...(data.lang === undefined ? {} : { lang: data.lang }),
      items: data.items.map((item) => ({ question: item.question, ...(item.state ? { state: { ...item.state } } : {}) })),
    },
  };
}
