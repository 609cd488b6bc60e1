// A homework sheet (what a lecturer composes), read from untrusted JSON: every field is checked
// and anything unexpected is refused with a reason. Handed-in files: gradeHandIn.js.
import { questionById } from './questions.js';
import { EMBED_KEYS } from '../host/readEmbedOptions.js';
import { clipText, rawText, resolveKey } from '../host/params.js';
import { panelSchema } from '../panels/panelSchema.js';

export const SHEET_VERSION = 1;
const MAX_ITEMS = 40;
const MAX_STATE_KEYS = 24;
const text = (v, max) => typeof v === 'string' && v.length > 0 && v.length <= max;
const plainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const SHEET_FIELDS = ['version', 'title', 'reveal', 'seed', 'items'];
const ITEM_FIELDS = ['question', 'state'];

/** Fields a sheet or an item does not have, named: a typo such as "stat" would lose the start state unseen. */
const unknownFields = (object, fields, what, where = '') => Object.keys(object).filter((key) => !fields.includes(key))
  .map((key) => `${where}“${rawText(key, 32)}” is not a field of ${what} (${fields.join(', ')}).`);

/**
 * An item's start state: panel values the question does not set (a view, a roughness). Its shape
 * and its names are checked here (a name the panel does not know would be dropped there without a
 * word); the panel checks each value against its schema and says so on screen.
 */
function stateProblems(state, panelId, where) {
  if (state === undefined) return [];
  if (!plainObject(state)) return [`${where}: state must be an object of panel values.`];
  const entries = Object.entries(state);
  if (entries.length > MAX_STATE_KEYS) return [`${where}: state holds more than ${MAX_STATE_KEYS} values.`];
  return entries.flatMap(([key, value]) => {
    if (!/^[A-Za-z][A-Za-z0-9]{0,31}$/.test(key)) return [`${where}: “${clipText(key, 32)}” is not a panel value's name.`];
    // The frame's own options (which panel, locks, the deck's origin) are the sheet page's to set.
    if (EMBED_KEYS.includes(key)) return [`${where}: ${key} is not a panel value (it is an option of the embed page).`];
    if (resolveKey(panelSchema(panelId) ?? {}, key) === undefined) return [`${where}: ${key} is not a value of this question's panel.`];
    const fits = (typeof value === 'number' && Number.isFinite(value)) || typeof value === 'boolean' || text(value, 64);
    return fits ? [] : [`${where}: ${key} must be a number, true or false, or a short text.`];
  });
}

/** { ok: true, sheet } with the sheet's items normalised, or { ok: false, problems: [text] }. */
export function readSheet(data) {
  const problems = [];
  if (!data || typeof data !== 'object' || Array.isArray(data)) return { ok: false, problems: ['A sheet is a JSON object.'] };
  problems.push(...unknownFields(data, SHEET_FIELDS, 'a sheet'));
  if (data.version !== SHEET_VERSION) problems.push(`version must be ${SHEET_VERSION}.`);
  if (!text(data.title, 200)) problems.push('title must be a text of 1 to 200 characters.');
  if (!Array.isArray(data.items) || data.items.length === 0 || data.items.length > MAX_ITEMS) {
    problems.push(`items must be a list of 1 to ${MAX_ITEMS} questions.`);
  } else {
    data.items.forEach((item, i) => {
      if (plainObject(item)) problems.push(...unknownFields(item, ITEM_FIELDS, 'an item', `item ${i + 1}: `));
      const question = questionById(item?.question);
      // rawText: the id may be any JSON, and String() of an object whose toString is not a function throws.
      if (!question) problems.push(`item ${i + 1}: there is no question “${rawText(item?.question)}”.`);
      else problems.push(...stateProblems(item.state, question.panel, `item ${i + 1}`));
    });
  }
  if (data.seed !== undefined && !text(data.seed, 64)) problems.push('seed, where given, must be a text of 1 to 64 characters.');
  if (data.reveal !== undefined && !['after-answer', 'lecturer'].includes(data.reveal)) problems.push('reveal must be '
    + 'after-answer or lecturer.');
  if (problems.length) return { ok: false, problems };
  return {
    ok: true,
    sheet: {
      version: SHEET_VERSION,
      title: data.title,
      reveal: data.reveal ?? 'after-answer',
      ...(data.seed === undefined ? {} : { seed: data.seed }),
      items: data.items.map((item) => ({ question: item.question, ...(item.state ? { state: { ...item.state } } : {}) })),
    },
  };
}
