// The languages the lab speaks, and which one a reader gets. Pure: no DOM, no storage (language.js
// reads those). English is the source catalogue; another language is one more file in locales/
// and one line here (its name as its speakers write it, its direction). The pseudo-locales come
// from the English catalogue (scripts/pseudoLocale.js): never picked from a browser's languages,
// only asked for by name (?lang=en-XA), for the tests.
import { safeLocale } from '../ui/safeLocale.js';

/**
 * numbers: the locale its shown numbers and its dates are written in.
 * @typedef {{ id: string, name: string, dir: 'ltr' | 'rtl', numbers: string }} Language
 */

/** @type {readonly Language[]} */
export const LANGUAGES = Object.freeze([
  { id: 'en', name: 'English', dir: 'ltr', numbers: 'en' },
  { id: 'es', name: 'Español', dir: 'ltr', numbers: 'es' },
]);

/** @type {readonly Language[]} */
export const PSEUDO_LANGUAGES = Object.freeze([
  { id: 'en-XA', name: '[Pseudo] Énglish', dir: 'ltr', numbers: 'en' },
  { id: 'ar-XB', name: '[Pseudo] right to left', dir: 'rtl', numbers: 'en' },
]);

export const SOURCE_LANGUAGE = 'en';

/**
 * The language with this exact id (a listed or a pseudo one), or undefined.
 * @param {unknown} id
 */
export function languageById(id) {
  return [...LANGUAGES, ...PSEUDO_LANGUAGES].find((l) => l.id === id);
}

/**
 * The listed language a tag asks for: its exact id, else its primary subtag (es-MX → es), through
 * safeLocale (en-US@posix, C, en_US.UTF-8 and '' never throw). Pseudo-locales only by exact id.
 * @param {unknown} tag
 * @returns {string | null}
 */
export function matchLanguage(tag) {
  if (typeof tag !== 'string' || !tag.trim()) return null;
  const exact = languageById(tag.trim());
  if (exact) return exact.id;
  const primary = safeLocale(tag).split('-')[0].toLowerCase();
  return LANGUAGES.find((l) => l.id === primary)?.id ?? null;
}

/**
 * Which language to speak, from what asks, strongest first: the link's ?lang=, then what the page
 * carries (an embed option, a lecture's or a sheet's language), then the reader's own choice kept
 * in this browser, then the browser's languages in order; English when none is spoken here.
 * @param {{ link?: unknown, carried?: unknown, stored?: unknown, browser?: readonly unknown[] }} asks
 */
export function pickLanguage({ link, carried, stored, browser = [] }) {
  for (const tag of [link, carried, stored, ...browser]) {
    const found = matchLanguage(tag);
    if (found) return found;
  }
  return SOURCE_LANGUAGE;
}
