// @ts-check
// The composer's lecture while it is written: a title, its language and an ordered list of items, each with a
// key of its own (so the page can keep an item's editor and its focus while the list is reordered)
// and every field present, empty or not. Pure functions that return a new draft; the lecture a
// draft gives is read back by readLecture, so what the composer offers as a link or a file is
// exactly what the lecture page accepts, and whatever it would leave out is named by position.
import { LECTURE_CAPS, LECTURE_KIND, LECTURE_VERSION, readLecture } from '../lecture/readLecture.js';
import { panelEntry } from '../panels/manifest.js';
import { questionById } from '../homework/questions.js';

/** @typedef {import('../lecture/readLecture.js').Lecture} Lecture */
import { panelTitle } from '../panels/panelText.js';
import english from 'virtual:messages/en/compose';
import { currentLanguage, messages } from '../i18n/messages.js';

const t = messages('compose', english);

/**
 * @typedef {{ key: string, type: 'panel', panel: string, state: import('../host/panelContract.js').Values, lock: string[], hide: string[],
 *   heading: string, text: string }} PanelDraft
 * @typedef {{ key: string, type: 'text', heading: string, text: string }} TextDraft
 * @typedef {{ key: string, type: 'question', question: string, seed: string, heading: string, text: string }} QuestionDraft
 * @typedef {PanelDraft | TextDraft | QuestionDraft} ItemDraft
 * @typedef {{ title: string, lang: string, items: ItemDraft[], nextKey: number }} Draft  lang: the lecture's language
 * @typedef {Omit<PanelDraft, 'key'> | Omit<TextDraft, 'key'> | Omit<QuestionDraft, 'key'>} NewItem  an item before addItem keys it
 * @typedef {Partial<Omit<PanelDraft, 'key' | 'type'> & Omit<QuestionDraft, 'key' | 'type'>>} ItemPatch  fields an editor changes
 */

/** The title of a new lecture ("My lecture"), in the page's language. */
export const defaultTitle = () => t('defaultTitle');

/**
 * A lecture with no items, in `lang` (by default the page's: a new lecture's words are written on it).
 * @returns {Draft}
 */
export function emptyDraft(title = defaultTitle(), lang = currentLanguage()) {
  return { title, lang, items: [], nextKey: 1 };
}

/**
 * A new panel item (no key yet: addItem gives it one).
 * @param {string} panel
 * @returns {Omit<PanelDraft, 'key'>}
 */
export const panelItem = (panel) => ({ type: 'panel', panel, state: {}, lock: [], hide: [], heading: '', text: '' });
/** @returns {Omit<TextDraft, 'key'>} */
export const textItem = (heading = '', text = '') => ({ type: 'text', heading, text });
/**
 * @param {string} question
 * @returns {Omit<QuestionDraft, 'key'>}
 */
export const questionItem = (question, seed = '') => ({ type: 'question', question, seed, heading: '', text: '' });

/**
 * The same item with its own copies of the state and key lists.
 * @param {NewItem} item
 * @returns {NewItem}
 */
function copyItem(item) {
  return item.type === 'panel' ? { ...item, state: { ...item.state }, lock: [...item.lock], hide: [...item.hide] } : { ...item };
}

/** @type {(draft: Draft, key: string) => number} */
const at = (draft, key) => draft.items.findIndex((item) => item.key === key);

/**
 * The draft with `item` added at `index` (the end by default). Returns { draft, key }. Beyond the
 * lecture's cap of items nothing is added (key null): the lecture page would read only the first.
 * @param {Draft} draft
 * @param {NewItem} item
 * @returns {{ draft: Draft, key: string | null }}
 */
export function addItem(draft, item, index = draft.items.length) {
  if (draft.items.length >= LECTURE_CAPS.items) return { draft, key: null };
  const key = `item-${draft.nextKey}`;
  const items = [...draft.items];
  items.splice(Math.max(0, Math.min(index, items.length)), 0, /** @type {ItemDraft} */ ({ ...copyItem(item), key }));
  return { draft: { ...draft, items, nextKey: draft.nextKey + 1 }, key };
}

/**
 * The draft with item `key` moved to position `index` (clamped to the list).
 * @param {Draft} draft
 * @param {string} key
 * @param {number} index
 */
export function moveItemTo(draft, key, index) {
  const from = at(draft, key);
  if (from < 0) return draft;
  const to = Math.max(0, Math.min(Math.trunc(index) || 0, draft.items.length - 1));
  if (to === from) return draft;
  const items = [...draft.items];
  const [item] = items.splice(from, 1);
  items.splice(to, 0, item);
  return { ...draft, items };
}

/** @type {(draft: Draft, key: string, delta: number) => Draft} The draft with item `key` moved `delta` places (−1: up one). */
export const moveItem = (draft, key, delta) => moveItemTo(draft, key, at(draft, key) + delta);

/**
 * The draft with a copy of item `key` right after it: { draft, key } (key: the copy's, or null).
 * @param {Draft} draft
 * @param {string} key
 */
export function duplicateItem(draft, key) {
  const i = at(draft, key);
  return i < 0 ? { draft, key: null } : addItem(draft, draft.items[i], i + 1);
}

/**
 * @param {Draft} draft
 * @param {string} key
 */
export function removeItem(draft, key) {
  return { ...draft, items: draft.items.filter((item) => item.key !== key) };
}

/**
 * The draft with fields of item `key` replaced (its key and type stay).
 * @param {Draft} draft
 * @param {string} key
 * @param {ItemPatch} patch  fields of the item's own type
 */
export function updateItem(draft, key, patch) {
  return {
    ...draft,
    items: draft.items.map((item) => (item.key === key ? /** @type {ItemDraft} */ ({ ...item, ...patch, key, type: item.type }) : item)),
  };
}

/** @type {(draft: Draft, title: string) => Draft} */
export const setTitle = (draft, title) => ({ ...draft, title });

/** @type {(draft: Draft, lang: string) => Draft} The lecturer's choice of the lecture's language. */
export const setLanguage = (draft, lang) => ({ ...draft, lang });

/** @type {(draft: Draft, key: string) => number} The position (0-based) of item `key`, or −1. */
export const itemIndex = (draft, key) => at(draft, key);

/**
 * The lecture's data as the draft holds it, before it is read: empty fields left out, and its
 * language, so that the lecture page, the deck and the offline lecture open in it. @param {Draft} draft
 */
export function draftData(draft) {
  const items = draft.items.map((item) => {
    /** @type {Record<string, unknown>} */
    const out = {};
    for (const [name, value] of Object.entries(item)) {
      if (name === 'key') continue;
      const empty = typeof value === 'string' ? !value.trim() : Array.isArray(value) ? !value.length
        : value !== null && typeof value === 'object' ? !Object.keys(value).length : value === undefined;
      if (!empty) out[name] = value;
    }
    return out;
  });
  return { kind: LECTURE_KIND, version: LECTURE_VERSION, title: draft.title, lang: draft.lang, items };
}

/**
 * The lecture the draft gives, as readLecture reads it, and what readLecture would leave out
 * (named "Item N" by the item's place in the list).
 * @param {Draft} draft
 * @returns {{ lecture: Lecture | null, problems: string[] }}
 */
export function draftToLecture(draft) {
  const read = readLecture(draftData(draft));
  // A draft is always a lecture's shape, so readLecture refuses none outright; be safe regardless.
  return read.ok ? { lecture: read.lecture, problems: read.problems } : { lecture: null, problems: read.problems };
}

/**
 * A draft to edit a lecture (as readLecture gives it), in the lecture's language: opening a lecture
 * on a page in another language does not make it that language's. One that carries none takes the
 * page's, as a new one does.
 * @param {{ title: string, lang?: string, items: readonly import('../lecture/readLecture.js').LectureItem[] }} lecture
 * @returns {Draft}
 */
export function draftFromLecture(lecture) {
  let draft = emptyDraft(lecture.title, lecture.lang ?? currentLanguage());
  for (const item of lecture.items) {
    const full = item.type === 'panel' ? { ...panelItem(item.panel), ...item }
      : item.type === 'question' ? { ...questionItem(item.question), ...item } : { ...textItem(), ...item };
    draft = addItem(draft, full).draft;
  }
  return draft;
}

/**
 * The title of a question's panel, or '?' for a question the lab does not have.
 * @param {string} id
 */
const questionPanelName = (id) => {
  const panel = questionById(id)?.panel;
  return panel !== undefined && panelEntry(panel) ? panelTitle(panel) : '?';
};

/** A short plain-text name of an item, for the list and what a screen reader is told. @param {ItemDraft} item */
export function itemName(item) {
  // A heading of the lecturer's own names the item, and the panel stays named beside it: two cards
  // of one panel must not differ by their headings alone.
  /** @param {string} name */
  const withHeading = (name) => (item.heading.trim() ? t('itemNameHeading', { heading: item.heading.trim(), name }) : name);
  if (item.type === 'panel') return withHeading(panelEntry(item.panel) ? panelTitle(item.panel) : item.panel);
  if (item.type === 'question') {
    return withHeading(t('itemNameQuestion', { title: questionPanelName(item.question) }));
  }
  return item.heading.trim() || item.text.trim().split('\n', 1)[0].slice(0, 60) || t('itemNameEmpty');
}

/** What kind of item it is, in words. @param {'panel' | 'text' | 'question'} type */
export const itemKind = (type) => t('itemKind', { type });
