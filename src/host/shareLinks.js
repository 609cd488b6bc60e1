// @ts-check
// Links that reproduce a panel: the lecture page scrolled to it, or the embed page alone.
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { writeParams } from './params.js';
import { embedLink } from './embedLink.js';
import { escapeHtml } from '../ui/escapeHtml.js';
import { lecturePrefix } from '../panels/manifest.js';
import { panelTitle } from '../panels/panelText.js';

const t = messages('host', english);

/** @typedef {{ id: string, schema: import('./panelContract.js').Schema }} LinkedPanel */
/** @typedef {Readonly<import('./panelContract.js').Values>} Values */

/**
 * "Fresnel Lab: <the panel's title>", a frame's title and a poster's heading.
 * @param {string} id
 */
export const labTitle = (id) => t('labTitle', { title: panelTitle(id) });

/** @param {string} page */
function pageUrl(page) {
  return new URL(page, window.location.href);
}

/**
 * The lecture page scrolled to the panel, with its values.
 * @param {LinkedPanel} panel
 * @param {Values} values
 */
export function lectureUrl(panel, values) {
  const url = pageUrl('./index.html');
  writeParams(panel.schema, values, url.searchParams, lecturePrefix(panel.id));
  url.hash = panel.id;
  return url.toString();
}

/**
 * options: the embed page's lock= and hide= (lists of keys), as a lecture's item has them.
 * @param {LinkedPanel} panel
 * @param {Values} values
 * @param {{ lock?: readonly string[], hide?: readonly string[] }} [options]
 */
export function embedUrl(panel, values, { lock = [], hide = [] } = {}) {
  return embedLink(pageUrl('./embed.html').href, panel, values, { lock, hide });
}

/**
 * An <iframe> snippet; attribute values are escaped, so no state can break out of the tag.
 * @param {LinkedPanel} panel
 * @param {Values} values
 * @param {{ width?: number, height?: number, lock?: readonly string[], hide?: readonly string[] }} [options]
 */
export function embedCode(panel, values, { width = 960, height = 720, ...options } = {}) {
  return `<iframe src="${escapeHtml(embedUrl(panel, values, options))}" width="${width}" height="${height}" `
    + `style="border:0" loading="lazy" title="${escapeHtml(labTitle(panel.id))}" `
    + 'allow="fullscreen; clipboard-write"></iframe>';
}

/**
 * A panel of a composed lecture: the lecture page with the lecture (`code`, or none where the page
 * itself holds it: `page` is then that page's address), this item's state under its own prefix (what
 * differs from the item's start, `schema` holding that start as its defaults), and the item in the hash;
 * with `lang`, the language the lecture is read in (its link's, which the page needs before it reads the lecture).
 * @param {{ page?: string, code?: string | null, lang?: string | null, schema: import('./panelContract.js').Schema,
 *   prefix: string, key: string }} item
 * @param {Values} values
 */
export function itemLectureUrl({ page = './index.html', code = null, lang = null, schema, prefix, key }, values) {
  const url = pageUrl(page);
  url.search = '';
  if (code) url.searchParams.set('lecture', code);
  if (lang) url.searchParams.set('lang', lang);
  writeParams(schema, values, url.searchParams, prefix);
  url.hash = key;
  return url.toString();
}
