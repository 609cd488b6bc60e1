// The words the lab shows, by namespace and key from the message catalogues (locales/*.json,
// compiled by scripts/messagesPlugin.js). A module that shows words imports its namespace's
// English functions and makes its t():
//   import english from 'virtual:messages/en/spheres';
//   const t = messages('spheres', english);
//   t('lede'), t('readout', { theta: angle(x) })
// t() speaks the page's language once it is loaded (setCatalogue, from language.js), and English
// for any key that language lacks. Numbers go in already formatted (src/ui/format.js), so every
// digit shown keeps the lab's rounding.

/** @typedef {(args?: Record<string, unknown>) => string} Message  one compiled message */
/** @typedef {Record<string, Record<string, Message>>} Catalogue  namespace → key → message */

/** @type {Catalogue | null} */
let catalogue = null;
let current = 'en';

/** The language whose catalogue t() speaks. */
export const currentLanguage = () => current;

/**
 * The compiled catalogue of `lang` (null for the source language): every t() made before or after
 * speaks it from now on.
 * @param {string} lang
 * @param {Catalogue | null} compiled
 */
export function setCatalogue(lang, compiled) {
  current = lang;
  catalogue = compiled;
}

/**
 * t(key, args) for one namespace: the page's language, else English. A key that is in neither is
 * a mistake of the code, shown as the key itself in brackets so that it stands out (and fails the
 * pseudo-locale test) rather than breaking the page.
 * @param {string} namespace
 * @param {Record<string, Message>} english
 * @returns {(key: string, args?: Record<string, unknown>) => string}
 */
export function messages(namespace, english) {
  return (key, args) => {
    const own = catalogue?.[namespace];
    const message = (own && Object.hasOwn(own, key) ? own[key] : undefined) ?? (Object.hasOwn(english, key) ? english[key] : undefined);
    return message ? message(args) : `[${namespace}.${key}]`;
  };
}

/**
 * The message at namespace.key in the page's language only (not English), or undefined: what the
 * build wrote in English into a page (translatePage.js) stays where the language lacks a message.
 * @param {string} namespace @param {string} key @param {Record<string, unknown>} [args]
 */
export function translated(namespace, key, args) {
  const own = catalogue?.[namespace];
  return own && Object.hasOwn(own, key) ? own[key](args) : undefined;
}
