// For tests of words: the page's catalogue switched to the pseudo-locale en-XA (every message
// accented and bracketed ⟦…⟧, scripts/pseudoLocale.js) for the tests of one file, and the letters
// of a text that lie outside every bracket (words that did not come from the catalogue).
import { afterAll, beforeAll } from 'vitest';
import pseudo from 'virtual:messages/en-XA';
import { setCatalogue } from '../../src/i18n/messages.js';

/** Every t() speaks en-XA during this file's tests, English again after them. */
export function usePseudoLocale() {
  beforeAll(() => setCatalogue('en-XA', pseudo));
  afterAll(() => setCatalogue('en', null));
}

/** The words (two letters or more) of `text` outside ⟦…⟧, joined by spaces; '' when there are none. */
export function wordsOutside(text) {
  let depth = 0;
  let out = '';
  for (const ch of String(text)) {
    if (ch === '⟦') depth += 1;
    else if (ch === '⟧') depth = Math.max(0, depth - 1);
    else out += depth ? ' ' : ch;
  }
  return (out.match(/\p{L}{2,}/gu) ?? []).join(' ');
}
