// @ts-check
// One locale that Intl accepts, for every Intl formatter, collator and toLocale…String in the lab.
// Browsers pass on what the system reports, and not all of it is a BCP 47 tag: Chromium on Linux
// under LANG=C.UTF-8 reports `en-US@posix`, other setups `C`, `C.UTF-8`, `en_US.UTF-8`, `de_DE` or
// nothing, and Intl throws "Invalid language tag" on each. Those are POSIX locale names,
// language[_territory][.codeset][@modifier] (POSIX.1-2017, section 8.2), where C and POSIX name the
// portable locale, whose messages are English. A tag that still does not read falls back to English.
// Dates, times and sorting follow the page's language (setPageLanguage, from src/i18n/language.js),
// in the browser's own regional form of it where the browser speaks it (en-GB writes 05/12/2026).

/** The locale when nothing usable was reported: the language the lab is written in. */
export const FALLBACK_LOCALE = 'en';

// Longer than any real tag (the longest registered are about 40 characters); what is longer is refused.
const MAX_TAG = 100;
// The first of a reported list that reads is taken; no browser reports more than a few.
const MAX_TAGS = 16;

/**
 * One reported name as a canonical BCP 47 tag, FALLBACK_LOCALE for C or POSIX, or null.
 * @param {unknown} reported
 */
function readTag(reported) {
  if (typeof reported !== 'string' || reported.length > MAX_TAG) return null;
  const tag = reported.trim().split('@')[0].split('.')[0].replaceAll('_', '-');
  if (tag === '') return null;
  if (/^(c|posix)$/i.test(tag)) return FALLBACK_LOCALE;
  try {
    return Intl.getCanonicalLocales(tag)[0] ?? null;
  } catch {
    return null; // not a tag even after the POSIX parts are gone
  }
}

/**
 * A locale every Intl constructor accepts, from what a browser or a page reports: a tag or a list
 * of them (navigator.languages), the first that reads winning. `@modifier` and `.codeset` are
 * dropped, `_` becomes `-`, C and POSIX are English, and the tag is canonicalized
 * (`en_us.UTF-8` → `en-US`); anything else, or nothing, gives FALLBACK_LOCALE.
 * @param {unknown} reported
 * @returns {string}
 */
export function safeLocale(reported) {
  const list = Array.isArray(reported) ? reported.slice(0, MAX_TAGS) : [reported];
  for (const item of list) {
    const tag = readTag(item);
    if (tag) return tag;
  }
  return FALLBACK_LOCALE;
}

/** The page's language as a tag (setPageLanguage), or null before a page chooses one. */
let pageLanguage = /** @type {string | null} */ (null);

/**
 * Dates, times and sorting follow `language` from now on (made safe here); null: the browser's
 * languages, as before a page chose one.
 * @param {unknown} language
 */
export function setPageLanguage(language) {
  pageLanguage = language === null || language === undefined ? null : safeLocale(language);
}

/**
 * The locale that writes `language` for a reader whose browser reports `reported` (a tag or a
 * list): the first reported tag in that language, with its region (English in a British browser:
 * en-GB), else the language itself. Made safe: an invalid tag gives English, never a throw.
 * @param {unknown} language
 * @param {unknown} reported
 * @returns {string}
 */
export function localeFor(language, reported) {
  const tag = safeLocale(language);
  const primary = tag.split('-')[0];
  for (const item of Array.isArray(reported) ? reported.slice(0, MAX_TAGS) : [reported]) {
    const own = readTag(item);
    if (own && own.split('-')[0] === primary) return own;
  }
  return tag;
}

/**
 * The reader's locale: the page's language (setPageLanguage) in the browser's form of it, else the
 * browser's languages in order of preference; made safe. English where there is neither (Node).
 * @returns {string}
 */
export function pageLocale() {
  const nav = globalThis.navigator;
  const reported = nav ? [...(Array.isArray(nav.languages) ? nav.languages.slice(0, MAX_TAGS) : []), nav.language] : [];
  if (pageLanguage) return localeFor(pageLanguage, reported);
  return safeLocale(reported);
}
