// @ts-check
// The class view's worker in the language of the page that started it: a worker has modules of its
// own, so the catalogue the page chose (src/i18n/language.js) is not its until it sets it too. Its
// words are those of three namespaces (the refusals, flags, summaries and explanations it writes),
// which travel in the worker for every language (a worker's bundle cannot load a chunk, and each
// whole catalogue would more than double it). A pseudo-locale is made here from English, each
// message accented, bracketed ⟦…⟧ and padded as the build's are (scripts/pseudoLocale.js), rather
// than carried: a word that is not the catalogue's still stands out. Its arguments are accented
// with it, as the words are written whole. Shown numbers take the language's
// decimal sign.
import every from 'virtual:messages/every/class+homework+questions';
import classWords from 'virtual:messages/en/class';
import homeworkWords from 'virtual:messages/en/homework';
import questionWords from 'virtual:messages/en/questions';
import { LANGUAGES, PSEUDO_LANGUAGES, SOURCE_LANGUAGE, languageById } from '../../i18n/languages.js';
import { currentLanguage, setCatalogue } from '../../i18n/messages.js';
import { setNumberLocale } from '../../ui/format.js';
import { accent } from '../../i18n/pseudoAccent.js';

const ENGLISH = { class: classWords, homework: homeworkWords, questions: questionWords };
const GROWTH = 0.35; // as scripts/pseudoLocale.js

/** @typedef {import('../../i18n/messages.js').Message} Message */

/**
 * English's messages of one namespace, each bracketed and about 35 % longer.
 * @param {Record<string, Message>} english
 * @returns {Record<string, Message>}
 */
const pseudo = (english) => Object.fromEntries(Object.entries(english).map(([key, message]) => {
  /** @type {Message} */
  const padded = (args) => {
    const text = message(args);
    return `⟦${accent(text)} ${'·'.repeat(Math.ceil(GROWTH * text.length))}⟧`;
  };
  return [key, padded];
}));

/**
 * The compiled catalogue of `id` for this worker's namespaces, or null where it has none.
 * @param {string} id
 * @returns {import('../../i18n/messages.js').Catalogue | null}
 */
function catalogueOf(id) {
  if (PSEUDO_LANGUAGES.some((l) => l.id === id)) {
    return Object.fromEntries(Object.entries(ENGLISH).map(([namespace, messages]) => [namespace, pseudo(messages)]));
  }
  return Object.hasOwn(every, id) ? every[id] : null;
}

/**
 * Makes `id` (a language of the lab; anything else is English) the language of this worker's words.
 * @param {unknown} id
 * @returns {string} the language now spoken
 */
export function useWorkerLanguage(id) {
  const english = LANGUAGES[0]; // the first listed is the source language
  const asked = languageById(id) ?? english;
  const compiled = asked.id === SOURCE_LANGUAGE ? null : catalogueOf(asked.id);
  const language = compiled || asked.id === SOURCE_LANGUAGE ? asked : english;
  if (language.id !== currentLanguage()) {
    setCatalogue(language.id, compiled);
    setNumberLocale(language.numbers);
  }
  return language.id;
}
