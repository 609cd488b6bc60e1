// Pseudo-locales made from the English catalogue, so that a test can see every word the lab shows
// come from the catalogue and fit its place: each message's text accented (the letters stay
// readable), about 35 % longer (the growth of a long translation) and bracketed ⟦ … ⟧, so a word
// outside brackets on screen was never in the catalogue. Arguments, plural and select branches and
// markup tags (<sub>…</sub>) are kept as they are. Parsed with @messageformat/parser and written
// back in ICU MessageFormat.
import { parse } from '@messageformat/parser';
import { accent } from '../src/i18n/pseudoAccent.js';

export const OPEN = '⟦';
export const CLOSE = '⟧';
const GROWTH = 0.35;

/**
 * The words inside a tag of the markup bracketed too (<a …>⟦Hómé⟧</a>): on the page they are an
 * element's own text, apart from the message's brackets around it, and a test reads each element's text.
 */
const bracketTagged = (text) => text.replace(/(<([a-z][a-z0-9]*)\b[^>]*>)([^<]*\p{L}{2}[^<]*)(<\/\2>)/giu, `$1${OPEN}$3${CLOSE}$4`);

/** Text as it must be written inside an ICU message (apostrophes doubled; braces and # quoted). */
const quote = (text, inPlural) => text.replace(/'/g, "''").replace(inPlural ? /[{}#]+/g : /[{}]+/g, (m) => `'${m}'`);

function write(tokens, inPlural = false) {
  return tokens.map((token) => {
    switch (token.type) {
      case 'content': return quote(bracketTagged(accent(token.value)), inPlural);
      case 'argument': return `{${token.arg}}`;
      case 'function': return `{${token.arg}, ${token.key}${token.param ? `, ${write(token.param)}` : ''}}`;
      case 'octothorpe': return '#';
      default: {
        const offset = token.pluralOffset ? ` offset:${token.pluralOffset}` : '';
        const cases = token.cases.map((c) => `${c.key} {${write(c.tokens, token.type !== 'select')}}`).join(' ');
        return `{${token.arg}, ${token.type},${offset} ${cases}}`;
      }
    }
  }).join('');
}

/** Letters in a message's text (not its arguments), for the growth. */
const textLength = (tokens) => tokens.reduce((n, t) => n + (t.type === 'content' ? t.value.replace(/<[^>]*>/g, '').length
  : t.cases ? Math.max(0, ...t.cases.map((c) => textLength(c.tokens))) : 0), 0);

/**
 * One message, pseudo-localised. The growth is words of at most eight dots: a long message grows
 * as a translation does, by more words, never by one word no line can hold.
 */
export function pseudoMessage(message) {
  const tokens = parse(message);
  const pad = Array.from({ length: Math.ceil(GROWTH * textLength(tokens)) }, (_, i) => (i % 9 === 8 ? ' ' : '·')).join('').trimEnd();
  return `${OPEN}${write(tokens)}${pad ? ` ${pad}` : ''}${CLOSE}`;
}

/** A whole catalogue ({ namespace: { key: message } }), pseudo-localised. */
export function pseudoCatalogue(english) {
  return Object.fromEntries(Object.entries(english).map(([namespace, messages]) => [namespace,
    Object.fromEntries(Object.entries(messages).map(([key, message]) => [key, pseudoMessage(message)]))]));
}
