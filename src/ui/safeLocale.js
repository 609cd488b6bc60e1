// @ts-check
// One locale that Intl accepts, for every Intl formatter, collator and toLocale…String in the lab.
// Browsers pass on what the system reports, and not all of it is a BCP 47 tag: Chromium on Linux
// under LANG=C.UTF-8 reports `en-US@posix`, other setups `C`, `C.UTF-8`, `en_US.UTF-8`, `de_DE` or
// nothing, and Intl throws "Invalid language tag" on each. Those are POSIX locale names,
// language[_territory][.codeset][@modifier] (POSIX.1-2017, section 8.2), where C and POSIX name the
// portable locale, whose messages are English. A tag that still does not read falls back to English.

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

/**
 * The reader's locale: the browser's languages in order of preference, made safe; English where
 * there is no browser (Node).
 * @returns {string}
 */
export function pageLocale() {
  const nav = globalThis.navigator;
  if (!nav) return FALLBACK_LOCALE;
  return safeLocale([...(Array.isArray(nav.languages) ? nav.languages.slice(0, MAX_TAGS) : []), nav.language]);
}
