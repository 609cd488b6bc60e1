// Every language the lab lists is whole: each message of the English catalogue (locales/en.json,
// the source) is in its catalogue with the same ICU arguments (names, plural and select structure)
// and the same markup tags, and compiles under that language's plural rules. A message left out
// would show in English in the middle of another language; an argument renamed would print empty.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import MessageFormat from '@messageformat/core';
import { parse } from '@messageformat/parser';
import { LANGUAGES, SOURCE_LANGUAGE } from '../../src/i18n/languages.js';

const read = (lang) => JSON.parse(readFileSync(resolve(import.meta.dirname, `../../locales/${lang}.json`), 'utf8'));
const english = read(SOURCE_LANGUAGE);

/** The arguments of a parsed message: "argument:name", "plural:n", … (case texts left out). */
function shape(tokens, out = new Set()) {
  for (const token of tokens) {
    if (token.type === 'argument') out.add(`argument:${token.arg}`);
    if (token.type === 'function') out.add(`function:${token.arg}:${token.key}`);
    if (token.cases) {
      out.add(`${token.type}:${token.arg}`);
      for (const c of token.cases) shape(c.tokens, out);
    }
  }
  return out;
}
const argumentsOf = (message) => [...shape(parse(message))].sort();
/**
 * A translation's arguments as English's: a plural or select over an argument English prints as it
 * is counts as that argument (Spanish needs "1 acierto" where English writes "1 right").
 */
const argumentsAsEnglish = (own, message) => {
  const source = new Set(argumentsOf(message));
  return [...new Set(argumentsOf(own).map((a) => {
    const [, arg] = /^(?:plural|selectordinal|select):(.+)$/.exec(a) ?? [];
    return arg !== undefined && !source.has(a) && source.has(`argument:${arg}`) ? `argument:${arg}` : a;
  }))].sort();
};
const tagsOf = (message) => (message.match(/<\/?[a-z][a-z0-9]*\b[^>]*>/gi) ?? []).sort();

describe.each(LANGUAGES.filter((l) => l.id !== SOURCE_LANGUAGE).map((l) => l.id))('locales/%s.json', (lang) => {
  const catalogue = read(lang);
  const compiler = new MessageFormat(lang);

  it('has every namespace and key of the English catalogue, and no other', () => {
    const keys = (c) => Object.entries(c).flatMap(([ns, messages]) => Object.keys(messages).map((k) => `${ns}.${k}`)).sort();
    expect(keys(catalogue)).toEqual(keys(english));
  });

  it('gives each message the English arguments and markup, and each compiles', () => {
    const problems = [];
    for (const [ns, messages] of Object.entries(english)) {
      for (const [key, message] of Object.entries(messages)) {
        const own = catalogue[ns]?.[key];
        if (typeof own !== 'string') continue; // the test above names it
        const where = `${ns}.${key}`;
        try {
          compiler.compile(own);
        } catch (error) {
          problems.push(`${where}: ${error.message}`);
          continue;
        }
        const args = argumentsAsEnglish(own, message);
        if (args.join() !== argumentsOf(message).join()) problems.push(`${where}: arguments ${args} ≠ ${argumentsOf(message)}`);
        if (tagsOf(own).join() !== tagsOf(message).join()) problems.push(`${where}: markup ${tagsOf(own)} ≠ ${tagsOf(message)}`);
      }
    }
    expect(problems).toEqual([]);
  });
});

describe('Spanish counts', () => {
  it('a class summary says 1 acierto and 2 fallos, not 1 aciertos', () => {
    const share = new MessageFormat('es').compile(read('es').class['summary.share']);
    const text = share({ share: '33 %', right: 1, wrong: 2, unanswered: 0, students: 3, studentsN: '3' });
    expect(text).toBe('33 % de aciertos: 1 acierto, 2 fallos, 0 sin responder, de 3 estudiantes.');
  });
});
