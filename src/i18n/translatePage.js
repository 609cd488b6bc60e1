// A page's own words in the page's language: the elements the build wrote in English from the
// catalogue (data-i18n="namespace.key", data-i18n-attr="aria-label:namespace.key …"; see
// scripts/messagesPlugin.js) get the same messages in the language chosen, and the lecture page's
// panel sections their headings, ledes and citations. Where the language lacks a message, the
// English the build wrote stays.
import { translated } from './messages.js';
import { setRichText } from './richText.js';

const at = (/** @type {string} */ path) => {
  const dot = path.indexOf('.');
  return translated(path.slice(0, dot), path.slice(dot + 1));
};

/** @param {ParentNode} root */
export function translatePage(root) {
  for (const element of root.querySelectorAll('[data-i18n]')) {
    const message = at(element.getAttribute('data-i18n') ?? '');
    if (message === undefined) continue;
    if (element.hasAttribute('data-i18n-rich')) setRichText(/** @type {HTMLElement} */ (element), message);
    else element.textContent = message;
  }
  for (const element of root.querySelectorAll('[data-i18n-attr]')) {
    for (const pair of (element.getAttribute('data-i18n-attr') ?? '').trim().split(/\s+/)) {
      const [attribute, path] = pair.split(':');
      const message = at(path);
      if (message !== undefined) element.setAttribute(attribute, message);
    }
  }
  // The panel sections the build wrote (manifest.js, sectionHtml): heading, lede and citation.
  for (const section of root.querySelectorAll('section[data-panel]')) {
    const id = section.getAttribute('data-panel');
    /** @type {[string, string | undefined][]} */
    const parts = [
      ['h2', translated('panels', `${id}.titleHtml`) ?? translated('panels', `${id}.title`)],
      ['.lede-text', translated('panels', `${id}.lede`)],
      ['.cite', translated('panels', `${id}.cite`)],
    ];
    for (const [selector, message] of parts) {
      const element = section.querySelector(selector);
      if (element && message !== undefined) {
        setRichText(/** @type {HTMLElement} */ (element), selector === '.cite' ? `(${message})` : message);
      }
    }
  }
}
