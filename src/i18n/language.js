// @ts-check
// The page's language, chosen once as the page starts (languages.js says which, from the link, what
// the page carries, the reader's choice kept in this browser and the browser's languages): its
// catalogue loaded (English ships with the page; another language is one chunk, fetched only when
// chosen), <html lang dir> set, shown numbers given its decimal separator and dates its form. A
// reader's change of language is kept in this browser and reloads the page, which then starts in
// it: every word on the page is written once, in one language.
import loaders from 'virtual:messages/languages';
import { LANGUAGES, SOURCE_LANGUAGE, languageById, pickLanguage } from './languages.js';
import { setCatalogue } from './messages.js';
import { setNumberLocale } from '../ui/format.js';
import { setPageLanguage } from '../ui/safeLocale.js';
import english from 'virtual:messages/en/ui:languageNotCarried';
import { messages } from './messages.js';

const STORAGE_KEY = 'fresnel-lab:language';
const t = messages('ui', english);

/** The language this browser's reader chose on a page of the lab, or null. */
export function storedLanguage() {
  try {
    return globalThis.localStorage?.getItem(STORAGE_KEY) ?? null;
  } catch {
    return null; // storage refused (a sandboxed frame, a privacy setting): nothing was kept
  }
}

/**
 * Keeps the reader's choice for every page of the lab in this browser.
 * @param {string} id
 */
export function rememberLanguage(id) {
  try {
    globalThis.localStorage?.setItem(STORAGE_KEY, id);
  } catch {
    // refused storage: the choice holds for this page only
  }
}

/** The browser's languages, in its order of preference. */
const browserLanguages = () => (navigator.languages?.length ? [...navigator.languages] : [navigator.language]);

/**
 * Chooses the page's language and makes it the page's: resolves to its id once its catalogue is
 * here. carried: a language the page carries (an embed's option, a lecture's or a sheet's); stored:
 * false where the reader's kept choice must not count (an embed follows its deck, not the reader).
 * A catalogue that cannot load leaves the page in English, and says so in `problem`.
 * @param {{ carried?: unknown, stored?: boolean }} [options]
 * @returns {Promise<{ id: string, problem: string | null }>}
 */
export async function startLanguage({ carried = null, stored = true } = {}) {
  const link = new URLSearchParams(window.location.search).get('lang');
  const id = pickLanguage({ link, carried, stored: stored ? storedLanguage() : null, browser: browserLanguages() });
  try {
    await useLanguage(id);
    return { id, problem: null };
  } catch (error) {
    await useLanguage(SOURCE_LANGUAGE);
    return { id: SOURCE_LANGUAGE, problem: error instanceof Error ? error.message : String(error) };
  }
}

/**
 * Loads `id`'s catalogue and makes it the page's (lang, dir, numbers, dates and sorting).
 * @param {string} id
 */
export async function useLanguage(id) {
  const language = languageById(id) ?? LANGUAGES[0]; // the first listed is the source language, English
  // A single-file page carries the listed languages only, not the tests' pseudo-locales.
  const load = language.id === SOURCE_LANGUAGE ? null : loaders[language.id];
  if (load === undefined) throw new Error(t('languageNotCarried', { id: language.id }));
  const compiled = load ? (await load()).default : null;
  setCatalogue(language.id, compiled);
  setNumberLocale(language.numbers);
  setPageLanguage(language.numbers); // a pseudo-locale writes dates as its numbers, in English
  document.documentElement.lang = language.id;
  document.documentElement.dir = language.dir;
  return language;
}

/** The listed languages, for a selector (pseudo-locales are asked for by link only). */
export const languageChoices = () => LANGUAGES;
