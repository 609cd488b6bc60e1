// A message with markup (a lede with <sub>t</sub>, the keys help with <kbd> and a link) made into
// nodes, never through innerHTML: the catalogue is this repository's, but its markup is read as
// data all the same. Tags outside a small set are kept as their text; an attribute is kept only
// where it is safe (a link's href to a page of the lab or an http(s) address, a span's class).

const TAGS = new Set(['a', 'b', 'br', 'code', 'em', 'i', 'kbd', 'span', 'strong', 'sub', 'sup']);
/** @type {Record<string, string>} */
const ENTITIES = { amp: '&', lt: '<', gt: '>', quot: '"', apos: "'", nbsp: '\u00a0' };

/**
 * Text with its entities (&amp; &#8211; &#x2212;) decoded; an unknown entity is kept as written.
 * @param {string} text
 */
export function decodeEntities(text) {
  return text.replace(/&(#x[0-9a-f]+|#\d+|[a-z]+);/gi, (whole, /** @type {string} */ name) => {
    if (name[0] === '#') {
      const code = name[1] === 'x' || name[1] === 'X' ? Number.parseInt(name.slice(2), 16) : Number(name.slice(1));
      return Number.isInteger(code) && code > 0 && code <= 0x10ffff ? String.fromCodePoint(code) : whole;
    }
    return Object.hasOwn(ENTITIES, name) ? ENTITIES[name] : whole;
  });
}

const safeHref = (/** @type {string} */ href) => /^(\.{0,2}\/|#|https?:\/\/)/i.test(href) && !/^\s*javascript:/i.test(href);

/**
 * The attributes of an opening tag's text, as { name: value }.
 * @param {string} text
 * @returns {Record<string, string>}
 */
function attributesOf(text) {
  /** @type {Record<string, string>} */
  const found = {};
  for (const [, name, , quoted, bare] of text.matchAll(/([a-z-]+)(\s*=\s*(?:"([^"]*)"|([^\s"'>]+)))?/gi)) {
    found[name.toLowerCase()] = decodeEntities(quoted ?? bare ?? '');
  }
  return found;
}

/**
 * The nodes of `message` in `doc` (a DocumentFragment): text as text, the allowed tags as
 * elements. Unbalanced closing tags are dropped; unclosed ones close at the end.
 * @param {string} message
 * @param {Document} doc  the document the nodes belong to (the element's: setRichText)
 */
export function richText(message, doc) {
  const fragment = doc.createDocumentFragment();
  /** @type {(DocumentFragment | HTMLElement)[]} the fragment, then the open elements */
  const stack = [fragment];
  const top = () => stack[stack.length - 1];
  let last = 0;
  const text = (/** @type {string} */ t) => { if (t) top().append(doc.createTextNode(decodeEntities(t))); };
  for (const match of String(message).matchAll(/<(\/?)([a-z][a-z0-9]*)([^<>]*?)(\/?)>/gi)) {
    const [whole, closing, rawName, rest, selfClosing] = match;
    const name = rawName.toLowerCase();
    text(message.slice(last, match.index));
    last = match.index + whole.length;
    if (!TAGS.has(name)) { text(whole); continue; }
    if (closing) {
      // Past the fragment at 0, the stack holds elements only.
      const at = stack.findLastIndex((node, i) => i > 0 && /** @type {HTMLElement} */ (node).localName === name);
      if (at > 0) stack.length = at;
      continue;
    }
    const element = doc.createElement(name);
    const attributes = attributesOf(rest);
    if (name === 'a' && attributes.href && safeHref(attributes.href)) {
      element.setAttribute('href', attributes.href);
      if (/^https?:/i.test(attributes.href)) {
        element.setAttribute('target', '_blank');
        element.setAttribute('rel', 'noopener noreferrer');
      }
    }
    if (name === 'span' && attributes.class && /^[a-z][a-z0-9 -]*$/i.test(attributes.class)) element.className = attributes.class;
    top().append(element);
    if (!selfClosing && name !== 'br') stack.push(element);
  }
  text(message.slice(last));
  return fragment;
}

/**
 * An element's content made `message`'s nodes.
 * @param {Element} element
 * @param {string} message
 */
export function setRichText(element, message) {
  element.replaceChildren(richText(message, element.ownerDocument));
}

/**
 * Plain text of a message with markup: its tags dropped, its entities decoded.
 * @param {string} message
 */
export function plainText(message) {
  return decodeEntities(String(message).replace(/<[^<>]*>/g, ''));
}
