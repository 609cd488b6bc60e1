// @ts-check
// The list of the panels in the docs (docs/lecturer/panels.md), written from the panel manifest (src/panels/manifest.js: which
// panels, in which order, which draw with WebGL) and the English catalogue (locales/en.json: their
// titles and where in the lecture each comes from), between two markers: `npm run panel-list`
// rewrites it, and tests/unit/panelList.test.js fails while a file's list is not what this writes.
// The words are the catalogue's markup made Markdown: <sub>t</sub> as _t (the lab's n_t notation),
// <sup>, <i>, <em>, <b>, <strong> and <code> as their Markdown, entities decoded.
import { decodeEntities } from '../src/i18n/richText.js';

export const LIST_START = '<!-- panel list: written by `npm run panel-list` from src/panels/manifest.js and locales/en.json -->';
export const LIST_END = '<!-- end of the panel list -->';

const MARKDOWN = { sub: ['_', ''], sup: ['^', ''], i: ['*', '*'], em: ['*', '*'], b: ['**', '**'], strong: ['**', '**'], code: ['`', '`'] };

/** A catalogue message (markup) as Markdown for a table cell: its tags as Markdown, its text escaped. */
export function markdownText(markup) {
  return markup.split(/(<\/?[a-z]+[^>]*>)/i).map((part, i) => {
    if (i % 2 === 1) {
      const [, close, name] = /^<(\/?)([a-z]+)/i.exec(part);
      const pair = MARKDOWN[name.toLowerCase()];
      return pair ? pair[close ? 1 : 0] : '';
    }
    return decodeEntities(part).replace(/([\\`*[\]|])/g, '\\$1').replace(/</g, '&lt;').replace(/\s+/g, ' ');
  }).join('').trim();
}

/** What draws the panel, from its entry. */
const drawnWith = (entry) => (entry.webgl ? 'WebGL' : entry.webglAtTimes ? 'WebGL while it measures' : 'no WebGL');

/**
 * The list, markers included: one table row per panel in the lecture's order.
 * @param {readonly { id: string, webgl: boolean, webglAtTimes?: boolean }[]} panels
 * @param {Record<string, string>} words  the catalogue's "panels" namespace
 */
export function panelList(panels, words) {
  const at = (id, key) => (Object.hasOwn(words, `${id}.${key}`) ? words[`${id}.${key}`] : '');
  const rows = panels.map((entry, i) => `| ${i + 1} | ${markdownText(at(entry.id, 'titleHtml') || at(entry.id, 'title'))} | \`${entry.id}\` `
    + `| ${drawnWith(entry)} | ${markdownText(at(entry.id, 'cite'))} |`);
  return [
    LIST_START,
    'Each panel also opens alone, without the page around it, at `embed.html?panel=<id>`.',
    '',
    '| | panel | id | draws | where it comes from |',
    '|---|---|---|---|---|',
    ...rows,
    '', // the table ends before the marker, whatever reads the Markdown
    LIST_END,
  ].join('\n');
}

/**
 * `text` with the list between its markers replaced by `list`; null when the text has no list (or
 * the markers are out of order).
 * @param {string} text
 * @param {string} list
 */
export function withPanelList(text, list) {
  const start = text.indexOf(LIST_START);
  const end = text.indexOf(LIST_END, start);
  if (start < 0 || end < 0) return null;
  return text.slice(0, start) + list + text.slice(end + LIST_END.length);
}
