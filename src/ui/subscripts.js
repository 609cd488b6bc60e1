// Text in the lecture's notation with real subscripts: "n_i = 1.5" shows n with a subscript i.
// Built from DOM nodes (<sub> in HTML, a shifted <tspan> in SVG), never from HTML strings.
const SUBSCRIPT = /([A-Za-zθλv])_([A-Za-z0-9]+)/g;
const SVG = 'http://www.w3.org/2000/svg';

/**
 * @param {Element} owner
 * @param {string} text
 */
function subscriptNode(owner, text) {
  if (owner.namespaceURI === SVG) {
    const span = document.createElementNS(SVG, 'tspan');
    span.setAttribute('baseline-shift', 'sub');
    span.setAttribute('font-size', '70%');
    span.textContent = text;
    return span;
  }
  const sub = document.createElement('sub');
  sub.textContent = text;
  return sub;
}

/**
 * Sets an element's content to `text` with every x_y written as x with subscript y.
 * @template {Element} E
 * @param {E} element
 * @param {string} text
 * @returns {E}
 */
export function setSubscripted(element, text) {
  /** @type {(string | Element)[]} */
  const nodes = [];
  let last = 0;
  for (const match of text.matchAll(SUBSCRIPT)) {
    nodes.push(text.slice(last, match.index + match[1].length), subscriptNode(element, match[2]));
    last = match.index + match[0].length;
  }
  nodes.push(text.slice(last));
  element.replaceChildren(...nodes.filter((n) => n !== ''));
  return element;
}
