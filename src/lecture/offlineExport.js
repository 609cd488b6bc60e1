// @ts-check
// A composed lecture as one file that opens from disk: the single-file lecture page that the build
// writes (dist/offline/index.html, scripts/buildOffline.js) with the lecture in it as a data element,
//   <script type="application/json" id="fresnel-lab-lecture">…</script>,
// which the lecture page reads when its link has no ?lecture= (the contract of issue 28).
// The JSON has every < written as \u003c (the same string to JSON.parse), so no text of the lecture
// can close the element or open a comment in it. The page's Content-Security-Policy meta needs no
// change: a script of type application/json is data, never run, so script-src does not govern it
// (and inlineTexts in scripts/contentSecurityPolicy.js leaves such blocks out of the hashes);
// reading its text is no fetch. Nothing else in the page depends on the lecture, but its <title>,
// which is set as the lecture page sets it (mountLecture.js) so the file's tab is named before any
// script runs. A question item's panel is a frame of ./embed.html: the file belongs beside it, so the
// composer offers the lecture with embed.html in one .zip (offlineLectureZip).
import { readLecture } from './readLecture.js';
import { LECTURE_ELEMENT_ID } from './lectureElement.js';
import { escapeHtml } from '../ui/escapeHtml.js';
import english from 'virtual:messages/en/lecture';
import { messages } from '../i18n/messages.js';

const t = messages('lecture', english);

export { LECTURE_ELEMENT_ID };

/**
 * The lecture's JSON as the text of a data element: every < as \u003c.
 * @param {import('./readLecture.js').Lecture} lecture
 */
export function lectureDataJson(lecture) {
  return JSON.stringify(lecture).replace(/</g, '\\u003c');
}

/**
 * The page's script elements in order, as [start, end, openTag]: under the HTML rules a script's
 * text ends at the first </script, which the built page's inlined bundles keep to.
 * @param {string} html
 */
function scriptElements(html) {
  /** @type {[number, number, string][]} */
  const found = [];
  const open = /<script\b[^>]*>/gi;
  let match;
  while ((match = open.exec(html))) {
    const close = html.slice(open.lastIndex).search(/<\/script\s*>/i);
    if (close < 0) break;
    const end = open.lastIndex + close + html.slice(open.lastIndex + close).indexOf('>') + 1;
    found.push([match.index, end, match[0]]);
    open.lastIndex = end;
  }
  return found;
}

/** @param {string} openTag */
const isLectureElement = (openTag) => new RegExp(`\\sid\\s*=\\s*["']?${LECTURE_ELEMENT_ID}["'\\s>]`, 'i').test(openTag);

/**
 * The offline lecture page (the text of dist/offline/index.html) holding `lecture`: read by
 * readLecture first (what the page would refuse is not written; a lecture with nothing usable
 * throws), its data element placed before the page's first script, any such element already there
 * replaced. Pure: the page's text in, the new text out.
 * @param {string} offlineIndexHtml
 * @param {unknown} lecture
 * @returns {string}
 */
export function offlineLectureHtml(offlineIndexHtml, lecture) {
  if (typeof offlineIndexHtml !== 'string' || !/<head[\s>]/i.test(offlineIndexHtml)) {
    throw new TypeError('The offline lecture page is not an HTML page.');
  }
  const read = readLecture(lecture);
  if (!read.ok) throw new TypeError(`This is no lecture: ${read.problems.join(' ')}`);
  let html = offlineIndexHtml;
  for (const [start, end, openTag] of scriptElements(html).reverse()) {
    if (isLectureElement(openTag)) html = html.slice(0, start).replace(/[ \t]*$/, '') + html.slice(end).replace(/^\r?\n/, '');
  }
  const element = `<script type="application/json" id="${LECTURE_ELEMENT_ID}">${lectureDataJson(read.lecture)}</script>`;
  const first = scriptElements(html)[0];
  const head = html.search(/<\/head\s*>/i);
  const at = first && (head < 0 || first[0] < head) ? first[0] : head;
  if (at < 0) throw new TypeError('The offline lecture page has no <head> to hold the lecture.');
  const indent = /[ \t]*$/.exec(html.slice(0, at))?.[0] ?? ''; // the pattern matches every text, at its end
  html = `${html.slice(0, at)}${element}\n${indent}${html.slice(at)}`;
  // The first <title> is the page's own (it comes before any script); the lecture's title, escaped.
  const title = /<title\b[^>]*>[^<]*<\/title>/i.exec(html);
  if (title && (!first || title.index < first[0])) {
    const named = `<title>${escapeHtml(t('pageTitle', { title: read.lecture.title }))}</title>`;
    html = `${html.slice(0, title.index)}${named}${html.slice(title.index + title[0].length)}`;
  }
  return html;
}

/**
 * The offline lecture as one download: a .zip of one folder that holds the lecture page and what its
 * frames open (the embed page of a question's panel and of Copy embed code, and the icon), so that
 * unpacked anywhere, from a USB stick too, index.html finds embed.html beside it. `pages` are the
 * texts of the offline folder's index.html, embed.html and favicon.svg; the folder is named after
 * the lecture (`folder`, a file-name slug). Returns the zip's bytes (fflate, stored as DEFLATE).
 * @param {{ index: string, embed: string, favicon?: string }} pages
 * @param {unknown} lecture
 * @param {string} folder
 */
export async function offlineLectureZip(pages, lecture, folder) {
  const { strToU8, zipSync } = await import('fflate');
  if (typeof pages.embed !== 'string' || !/<head[\s>]/i.test(pages.embed)) {
    throw new TypeError('The offline embed page is not an HTML page.');
  }
  /** @type {import('fflate').Zippable} */
  const files = {
    'index.html': strToU8(offlineLectureHtml(pages.index, lecture)),
    'embed.html': strToU8(pages.embed),
  };
  if (typeof pages.favicon === 'string') files['favicon.svg'] = strToU8(pages.favicon);
  return zipSync({ [folder]: files }, { level: 9 });
}
