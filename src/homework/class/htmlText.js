// @ts-check
// The text of an HTML file, for finding hand-in codes in it: an LMS's "online text" submission
// (Moodle's onlinetext.html, Canvas's …_text.html) is the student's text box as an HTML page.
// htmlparser2's tokenizer reads it as data: tags are dropped, entities decoded (&amp; → &), and
// nothing is rendered, fetched or run (it builds no DOM; DOMParser is not there in a worker
// anyway). Block elements and <br> become line breaks, so a code that a mail wrapped over lines
// is joined as it is in a .txt file; what a browser does not show (scripts, styles, comments,
// attributes) is left out. The caller caps the size (CLASS_CAPS.maxFileBytes); the tokenizer is
// one pass over the text.
import { Parser } from 'htmlparser2';

const BREAKS = new Set(['address', 'article', 'aside', 'blockquote', 'br', 'dd', 'div', 'dl', 'dt', 'figcaption', 'figure',
  'footer', 'h1', 'h2', 'h3', 'h4', 'h5', 'h6', 'header', 'hr', 'li', 'main', 'nav', 'ol', 'p', 'pre', 'section', 'table',
  'tbody', 'td', 'tfoot', 'th', 'thead', 'tr', 'ul', 'body', 'html', 'head', 'title']);
const HIDDEN = new Set(['script', 'style', 'template', 'noscript']);

/**
 * The text an HTML document shows, with a line break for each block and <br>. Never throws.
 * @param {string} html
 * @returns {string}
 */
export function htmlToText(html) {
  /** @type {string[]} */
  const parts = [];
  let hidden = 0;
  const parser = new Parser({
    onopentag(name) {
      if (HIDDEN.has(name)) hidden += 1;
      else if (BREAKS.has(name)) parts.push('\n');
    },
    onclosetag(name) {
      if (HIDDEN.has(name)) hidden = Math.max(0, hidden - 1);
      else if (BREAKS.has(name)) parts.push('\n');
    },
    ontext(text) {
      if (!hidden) parts.push(text);
    },
  }, { decodeEntities: true, lowerCaseTags: true, recognizeSelfClosing: false });
  try {
    parser.end(String(html));
  } catch {
    // Not expected of the tokenizer; what was read so far is kept.
  }
  return parts.join('');
}

/** Whether a text that starts with "<" reads as an HTML page or fragment (not "<3" or "<-- mine"). */
/** @param {string} text */
export const looksLikeHtml = (text) => /^\s*<(!doctype\s+html|html|head|body|meta|p|div|span|br|!--|h[1-6]|ul|ol|table|pre)[\s>/]/i
  .test(text.slice(0, 200));
