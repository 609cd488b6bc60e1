// Node module hooks for the browser tests' own process: a spec that imports the lab's modules to work
// out what to expect (scorm.spec.js plans answers with the question bank) meets the catalogues'
// virtual modules, which only Vite resolves (scripts/messagesPlugin.js). Here they resolve to the
// English catalogue compiled the same way, so the spec reads the same words as the built pages.
// Registered by playwright.config.js (module.register), in its workers too.
import { readFileSync } from 'node:fs';
import MessageFormat from '@messageformat/core';
import compileModule from '@messageformat/core/compile-module.js';
import { namespaceMessages } from '../../scripts/messagesPlugin.js';

const PREFIX = 'virtual:messages/';
const ROOT = new URL('../../', import.meta.url);

export async function resolve(specifier, context, next) {
  if (specifier.startsWith(PREFIX)) return { url: specifier, shortCircuit: true };
  // The compiled catalogue imports @messageformat/runtime: resolved from the project, not from its virtual URL.
  if (context.parentURL?.startsWith(PREFIX)) return next(specifier, { ...context, parentURL: new URL('package.json', ROOT).href });
  return next(specifier, context);
}

export async function load(url, context, next) {
  if (!url.startsWith(PREFIX)) return next(url, context);
  const [lang, spec] = url.slice(PREFIX.length).split('/');
  // Only English is compiled here: the specs expect the source language; other languages load in the pages.
  if (lang === 'languages') return { format: 'module', source: 'export default {};\n', shortCircuit: true };
  const english = JSON.parse(readFileSync(new URL('locales/en.json', ROOT), 'utf8'));
  const messages = lang === 'en' ? namespaceMessages(english, spec ?? '') : undefined;
  if (!messages) throw new Error(`${url}: only English namespaces are compiled for the specs.`);
  return { format: 'module', source: compileModule(new MessageFormat('en'), messages), shortCircuit: true };
}
