// @ts-check
// The lecturer's text on the page: the tree of lectureText.js made into elements with text nodes
// only (no HTML string is ever parsed), links opened in a new tab without the opener, and math
// typeset by KaTeX (ui/tex.js, fetched when first needed; the TeX source shows until then).
import { renderTex } from '../ui/tex.js';
import { lectureTextTree } from './lectureText.js';

/**
 * @param {import('./lectureText.js').TextNode} node
 * @returns {Node}
 */
function build(node) {
  if ('text' in node) return document.createTextNode(node.text);
  if ('math' in node) {
    const holder = document.createElement(node.display ? 'div' : 'span');
    holder.className = node.display ? 'lecture-math-display' : 'lecture-math';
    return renderTex(holder, node.math, { display: node.display });
  }
  const element = document.createElement(node.tag);
  if (element instanceof HTMLAnchorElement) {
    element.setAttribute('href', node.href ?? '');
    element.target = '_blank';
    element.rel = 'noopener noreferrer';
  }
  if (node.tag === 'ol' && node.start) element.setAttribute('start', String(node.start));
  element.append(...node.children.map(build));
  return element;
}

/**
 * The text's elements, in a fragment to append where the text belongs.
 * @param {unknown} source
 */
export function lectureTextFragment(source) {
  const fragment = document.createDocumentFragment();
  fragment.append(...lectureTextTree(source).map(build));
  return fragment;
}
