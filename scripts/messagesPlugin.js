// The message catalogues (locales/<lang>.json, ICU MessageFormat, English the source) compiled at
// build time into JavaScript functions (@messageformat/core's compileModule), so no message parser
// ships to the browser. Virtual modules:
//   virtual:messages/en/<namespace>  one namespace of the English catalogue; imported statically by
//                                    the modules that show its words, so English travels in the
//                                    chunks that use it and the first load carries only its own
//   virtual:messages/en/<ns>:<f>+<f> the keys of that namespace whose last part (after the last dot)
//                                    is one of those fields: panels:title+titleHtml, the panels'
//                                    headings, which every page needs, apart from their ledes
//   virtual:messages/<lang>          a whole other catalogue, loaded when that language is chosen
//   virtual:messages/languages       { <lang>: () => import(…) } for every other language
//   virtual:messages/every/<ns>+<ns> { <lang>: { <ns>: … } }: those namespaces of every other language
//                                    but the pseudo-locales, in one module (a worker's, whose bundle
//                                    cannot load chunks; it makes a pseudo-locale from English itself)
// The pseudo-locales en-XA (accented, 35 % longer, bracketed) and ar-XB (the same, right to left)
// are made from the English catalogue here (pseudoLocale.js), for the tests that find words outside
// the catalogue and text that is cut off.
// The pages' own words come from the catalogue too: an element written empty with
// data-i18n="namespace.key" gets the English message at build time (its markup as written where it
// also has data-i18n-rich, else escaped), and data-i18n-attr="aria-label:namespace.key …" sets
// attributes; src/i18n/translatePage.js puts another language in the same places at run time.
import { readFileSync, readdirSync } from 'node:fs';
import { resolve } from 'node:path';
import MessageFormat from '@messageformat/core';
import compileModule from '@messageformat/core/compile-module.js';
import { pseudoCatalogue } from './pseudoLocale.js';
import { escapeHtml } from '../src/ui/escapeHtml.js';

const PREFIX = 'virtual:messages';
const RESOLVED = `\0${PREFIX}`;
export const PSEUDO_LOCALES = Object.freeze({ 'en-XA': { dir: 'ltr' }, 'ar-XB': { dir: 'rtl' } });

/**
 * The catalogues in `dir`: { lang: { namespace: { key: message } } }, English first, with the
 * pseudo-locales unless `pseudo` is false (the single-file pages, which carry every language inline).
 */
export function readCatalogues(dir, pseudo = true) {
  const catalogues = {};
  for (const file of readdirSync(dir).filter((f) => f.endsWith('.json')).sort()) {
    catalogues[file.slice(0, -'.json'.length)] = JSON.parse(readFileSync(resolve(dir, file), 'utf8'));
  }
  if (!catalogues.en) throw new Error(`${dir}/en.json, the source catalogue, is missing.`);
  if (pseudo) for (const [lang, make] of Object.entries(PSEUDO_LOCALES)) catalogues[lang] = pseudoCatalogue(catalogues.en, make);
  return catalogues;
}


/** The English message at "namespace.key" (no arguments), or an error naming what is missing. */
function englishAt(english, path, file) {
  const dot = path.indexOf('.');
  const [namespace, key] = [path.slice(0, dot), path.slice(dot + 1)];
  const message = english[namespace]?.[key];
  if (typeof message !== 'string') throw new Error(`${file}: data-i18n “${path}” is not in locales/en.json`);
  return new MessageFormat('en').compile(message)({});
}

/** A page's HTML with its data-i18n elements and attributes written in English. */
export function fillPageText(html, english, file = 'page') {
  const withText = html.replace(/(<([a-z][a-z0-9]*)\b[^>]*\sdata-i18n="([\w.-]+)"[^>]*>)(<\/\2>)/gi, (whole, open, tag, path, close) => {
    const message = englishAt(english, path, file);
    return `${open}${/\sdata-i18n-rich\b/.test(open) ? message : escapeHtml(message)}${close}`;
  });
  return withText.replace(/\sdata-i18n-attr="([^"]*)"/g, (whole, list) => whole + list.trim().split(/\s+/).map((pair) => {
    const [attribute, path] = pair.split(':');
    return ` ${attribute}="${escapeHtml(englishAt(english, path, file))}"`;
  }).join(''));
}

/** The plural rules a language's messages are compiled with (a pseudo-locale uses English's). */
const pluralLocale = (lang) => (Object.hasOwn(PSEUDO_LOCALES, lang) ? 'en' : lang.split('-')[0]);

/**
 * The messages of `spec` in one language's catalogue: a namespace ("panels"), or part of one
 * ("panels:title+titleHtml": the keys whose last part, after the last dot, is one of those fields);
 * undefined where the catalogue has no such namespace.
 */
export function namespaceMessages(catalogue, spec) {
  const [namespace, fields] = spec.split(':');
  if (!Object.hasOwn(catalogue, namespace)) return undefined;
  const wanted = fields?.split('+');
  const whole = catalogue[namespace];
  return wanted ? Object.fromEntries(Object.entries(whole).filter(([key]) => wanted.includes(key.slice(key.lastIndexOf('.') + 1)))) : whole;
}

export function messagesPlugin({ dir, pseudo = true }) {
  let catalogues = null;
  const load = () => (catalogues ??= readCatalogues(dir, pseudo));
  return {
    name: 'fresnel-lab-messages',
    enforce: 'pre',
    resolveId(id) {
      return id === PREFIX || id.startsWith(`${PREFIX}/`) ? `\0${id}` : null;
    },
    load(id) {
      if (!id.startsWith(RESOLVED)) return null;
      for (const file of readdirSync(dir).filter((f) => f.endsWith('.json'))) this.addWatchFile(resolve(dir, file));
      const all = load();
      const parts = id.slice(RESOLVED.length + 1).split('/');
      if (parts[0] === 'languages') {
        const others = Object.keys(all).filter((lang) => lang !== 'en');
        return `export default {\n${others.map((lang) => `  ${JSON.stringify(lang)}: () => import(${JSON.stringify(`${PREFIX}/${lang}`)}),`).join('\n')}\n};\n`;
      }
      if (parts[0] === 'every') {
        const others = Object.keys(all).filter((lang) => lang !== 'en' && !Object.hasOwn(PSEUDO_LOCALES, lang));
        const namespaces = (parts[1] ?? '').split('+').filter(Boolean);
        const name = (i, j) => `m${i}_${j}`;
        const imports = others.flatMap((lang, i) => namespaces.map((ns, j) => `import ${name(i, j)} from ${JSON.stringify(`${PREFIX}/${lang}/${ns}`)};`));
        const entries = others.map((lang, i) => `  ${JSON.stringify(lang)}: { ${namespaces.map((ns, j) => `${JSON.stringify(ns)}: ${name(i, j)}`).join(', ')} },`);
        return `${imports.join('\n')}\nexport default {\n${entries.join('\n')}\n};\n`;
      }
      const [lang, spec] = parts;
      if (!Object.hasOwn(all, lang)) throw new Error(`No catalogue locales/${lang}.json for ${id}`);
      const messages = spec === undefined ? all[lang] : namespaceMessages(all[lang], spec);
      if (!messages) throw new Error(`locales/${lang}.json has no namespace “${spec}” (${id})`);
      return compileModule(new MessageFormat(pluralLocale(lang)), messages);
    },
    transformIndexHtml: {
      order: 'pre',
      handler(html, { filename }) {
        return fillPageText(html, load().en, filename);
      },
    },
    handleHotUpdate({ file, server }) {
      if (!file.startsWith(resolve(dir))) return undefined;
      catalogues = null;
      server.ws.send({ type: 'full-reload' });
      return [];
    },
  };
}
