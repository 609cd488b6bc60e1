// @ts-check
// The lecturer's text as HTML text, for files the lab writes (the reveal.js deck): the node tree
// of lectureText.js serialised with every text and attribute escaped, so no markup from a lecture
// reaches the file; only the tree's own tags are written, and links are those lectureText.js let
// through (http:, https:, mailto:). Math is typeset by KaTeX, as KaTeX's HTML with MathML for
// screen readers (math: 'html'; the file then carries KaTeX's CSS and fonts, katexDeckCss.js, so it
// looks as on the site) or as MathML alone (math: 'mathml'), which browsers draw with a math font
// of their own, if the machine has one. KaTeX escapes the TeX it quotes, and with trust off (its
// default) it refuses \href, \url and \html… commands; a formula it cannot read is shown as its source.
import katex from 'katex';
import { lectureTextTree } from './lectureText.js';
import { escapeHtml } from '../ui/escapeHtml.js';
import { texMacros } from '../ui/texMacros.js';

// The lecture's notation, as ui/subscripts.js writes it on the page: n_t is n with a subscript t.
const SUBSCRIPT = /([A-Za-zθλv])_([A-Za-z0-9]+)/g;

/**
 * Plain text (a question's prompt, a panel's title) as HTML, escaped, with x_y written as x<sub>y</sub>.
 * @param {string} text
 */
export function subscriptedHtml(text) {
  let html = '';
  let last = 0;
  for (const match of String(text).matchAll(SUBSCRIPT)) {
    html += `${escapeHtml(text.slice(last, match.index + match[1].length))}<sub>${escapeHtml(match[2])}</sub>`;
    last = match.index + match[0].length;
  }
  return html + escapeHtml(String(text).slice(last));
}

/**
 * TeX as KaTeX's HTML and MathML (math 'html') or MathML alone ('mathml'), or (TeX KaTeX cannot
 * read) its source as code; never throws.
 * @param {string} tex
 * @param {boolean} display
 * @param {'html' | 'mathml'} [math]
 */
export function mathHtml(tex, display, math = 'mathml') {
  const output = math === 'html' ? 'htmlAndMathml' : 'mathml';
  try {
    /** @type {import('katex').KatexOptions} */
    const options = { displayMode: display, output, throwOnError: true, trust: false, strict: 'ignore', macros: texMacros() };
    return katex.renderToString(tex, options);
  } catch {
    return `<code class="lecture-math-error">${escapeHtml(tex)}</code>`;
  }
}

/**
 * One node of the tree (lectureText.js's TextNode) as HTML, its math as `math` says (mathHtml).
 * @param {import('./lectureText.js').TextNode} node
 * @param {'html' | 'mathml'} math
 * @returns {string}
 */
function nodeHtml(node, math) {
  if ('text' in node) return escapeHtml(node.text);
  if ('math' in node) {
    const tag = node.display ? 'div' : 'span';
    return `<${tag} class="${node.display ? 'lecture-math-display' : 'lecture-math'}">${mathHtml(node.math, node.display, math)}</${tag}>`;
  }
  const inner = node.children.map((child) => nodeHtml(child, math)).join('');
  switch (node.tag) {
    case 'br':
      return '<br>';
    case 'a':
      // Opened in a new tab without the opener, as on the lecture page (lectureTextDom.js).
      return `<a href="${escapeHtml(node.href)}" target="_blank" rel="noopener noreferrer">${inner}</a>`;
    case 'ol':
      return node.start ? `<ol start="${Number(node.start)}">${inner}</ol>` : `<ol>${inner}</ol>`;
    case 'p': case 'ul': case 'li': case 'em': case 'strong': case 'code':
      return `<${node.tag}>${inner}</${node.tag}>`;
    default:
      return inner; // no other tag is ever in the tree; were one there, its text alone would be kept
  }
}

/**
 * The lecturer's Markdown (lectureText.js's subset) as HTML text. Never throws on any string.
 * @param {string} source
 * @param {{ math?: 'html' | 'mathml' }} [options]
 */
export function lectureTextHtml(source, { math = 'mathml' } = {}) {
  return lectureTextTree(source).map((node) => nodeHtml(node, math)).join('');
}
