// @ts-check
// The lecturer's text, a small Markdown: paragraphs, *emphasis* and **strong**, lists, `code`,
// links, and math as $inline$ and $$display$$ (typeset by KaTeX). Read by markdown-it with only
// those rules on (its "zero" preset: no raw HTML, no images, no headings or tables) and the math
// rules of @vscode/markdown-it-katex; its tokens become a plain tree of nodes, never an HTML string,
// so a lecture from anyone cannot put markup into the page. Links go only to http:, https: and
// mailto: (anything else stays text).
import MarkdownIt from 'markdown-it';
import markdownItKatex from '@vscode/markdown-it-katex';

const LINK = /^(https?:|mailto:)/i;

const md = new MarkdownIt('zero', { html: false, linkify: false, typographer: false, breaks: false })
  .enable(['emphasis', 'list', 'link', 'backticks', 'newline', 'escape', 'entity']);
// The plugin is CommonJS with exports.default: Node's import gives that exports object, the
// bundler the function itself, which its types describe.
const katexPlugin = /** @type {typeof markdownItKatex & { default?: typeof markdownItKatex }} */ (markdownItKatex);
// The plugin's own renderer is not used (the tree below is), so KaTeX is not needed to read: an
// empty object stands in for it.
const noKatex = /** @type {NonNullable<import('@vscode/markdown-it-katex').MarkdownKatexOptions['katex']>} */ ({});
(katexPlugin.default ?? katexPlugin)(md, { katex: noKatex });
md.validateLink = (/** @type {string} */ url) => LINK.test(url.trim());

/**
 * @typedef {{ text: string } | { math: string, display: boolean }
 *   | { tag: 'p' | 'ul' | 'ol' | 'li' | 'em' | 'strong' | 'code' | 'br' | 'a', href?: string, start?: number,
 *       children: TextNode[] }} TextNode
 */
/** @typedef {Extract<TextNode, { tag: string }>} ElementNode */

/** @type {Readonly<Record<string, 'p' | 'ul' | 'ol' | 'li'>>} */
const BLOCK = { paragraph_open: 'p', bullet_list_open: 'ul', ordered_list_open: 'ol', list_item_open: 'li' };
/** @type {Readonly<Record<string, 'em' | 'strong' | 'a'>>} */
const INLINE = { em_open: 'em', strong_open: 'strong', link_open: 'a' };

/**
 * Inline tokens → nodes.
 * @param {import('markdown-it').Token[]} tokens
 * @returns {TextNode[]}
 */
function inline(tokens) {
  /** @type {{ children: TextNode[] }} */
  const root = { children: [] };
  const stack = [root];
  const top = () => stack[stack.length - 1];
  for (const token of tokens) {
    if (Object.hasOwn(INLINE, token.type)) {
      /** @type {ElementNode} */
      const node = { tag: INLINE[token.type], children: [] };
      if (node.tag === 'a') node.href = String(token.attrGet('href') ?? ''); // a link token always has its href
      // markdown-it validates no empty target ("[x]()"): such a link's words stay plain text.
      if (node.tag === 'a' && !LINK.test(node.href?.trim() ?? '')) {
        stack.push(top());
        continue;
      }
      top().children.push(node);
      stack.push(node);
    } else if (token.type.endsWith('_close')) {
      if (stack.length > 1) stack.pop();
    } else if (token.type === 'code_inline') top().children.push({ tag: 'code', children: [{ text: token.content }] });
    else if (token.type === 'math_inline') top().children.push({ math: token.content, display: false });
    else if (token.type === 'math_inline_block') top().children.push({ math: token.content, display: true });
    else if (token.type === 'softbreak') top().children.push({ text: ' ' });
    else if (token.type === 'hardbreak') top().children.push({ tag: 'br', children: [] });
    else if (token.content) top().children.push({ text: token.content });
  }
  return root.children;
}

/**
 * The text as a tree of nodes (see TextNode). Never throws on any string.
 * @param {unknown} source
 * @returns {TextNode[]}
 */
export function lectureTextTree(source) {
  const tokens = md.parse(String(source ?? ''), {});
  /** @type {{ children: TextNode[] }} */
  const root = { children: [] };
  const stack = [root];
  const top = () => stack[stack.length - 1];
  for (const token of tokens) {
    // A tight list's paragraphs are hidden: its items hold their text directly.
    if (token.hidden && token.type.startsWith('paragraph_')) continue;
    if (Object.hasOwn(BLOCK, token.type)) {
      /** @type {ElementNode} */
      const node = { tag: BLOCK[token.type], children: [] };
      const start = Number(token.attrGet('start'));
      if (node.tag === 'ol' && Number.isInteger(start) && start > 1) node.start = start;
      top().children.push(node);
      stack.push(node);
    } else if (token.type.endsWith('_close')) {
      if (stack.length > 1) stack.pop();
    } else if (token.type === 'inline') {
      top().children.push(...inline(token.children ?? []));
    } else if (token.type === 'math_block') {
      top().children.push({ math: token.content.trim(), display: true });
    } else if (token.content) {
      top().children.push({ text: token.content });
    }
  }
  return root.children;
}
