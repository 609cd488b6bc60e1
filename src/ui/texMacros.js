// @ts-check
// The names a formula gives its functions in the page's language (Spanish writes sen and arcsen,
// as babel's Spanish option does for LaTeX), from the catalogue's `math` namespace: a namespace of
// its own, which only the modules that typeset import, so a first load carries none of it.
import english from 'virtual:messages/en/math';
import { messages } from '../i18n/messages.js';

const t = messages('math', english);

/**
 * KaTeX macros for the functions whose name the page's language writes otherwise: none where the
 * catalogue keeps TeX's name, or gives no plain word (as a pseudo-locale does). A new object each
 * time, since KaTeX may add to the one it is given.
 * @returns {Record<string, string>}
 */
export function texMacros() {
  /** @type {Record<string, string>} */
  const macros = {};
  for (const [command, key] of [['sin', 'sine'], ['arcsin', 'arcsine']]) {
    const name = t(key);
    if (name !== command && /^\p{L}+$/u.test(name)) macros[`\\${command}`] = `\\operatorname{${name}}`;
  }
  return macros;
}
