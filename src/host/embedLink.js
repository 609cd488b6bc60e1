// @ts-check
// The embed page's link for a panel, the one builder of it: the share link's "Copy embed code", a
// composed lecture's preview frame and a reveal.js deck's frames all write it here. `base?panel=ID`,
// the values that differ from the panel's defaults (as params.js writes a link), then the embed
// page's own options (readEmbedOptions.js reads them back): lock, hide, theme, projector, fit, lang.
// Lists keep their commas as written (lock=nI,nT): URLSearchParams reads "," and "%2C" alike, and a
// person reads and edits the first. Pure: the caller gives the page's address.
import { defaults, writeParams } from './params.js';

/**
 * @typedef {object} EmbedOptions
 * @property {readonly string[]} [lock]  keys shown but fixed
 * @property {readonly string[]} [hide]  keys not shown
 * @property {string | null} [theme]  'light' or 'dark'; null: the reader's
 * @property {boolean} [projector]
 * @property {boolean} [fit]          scaled down to show whole in its frame (a slide)
 * @property {string | null} [lang]   the language; null: the reader's
 */

/**
 * @param {string} base  embed.html's address, relative (offline/embed.html) or absolute; it may carry
 *   a query of its own, which the link keeps
 * @param {{ id: string, schema: import('./panelContract.js').Schema }} panel
 * @param {Readonly<import('./panelContract.js').Values>} [values]  the panel's values, all or some (the rest are its defaults)
 * @param {EmbedOptions} [options]
 * @returns {string}
 */
export function embedLink(base, panel, values = {}, {
  lock = [], hide = [], theme = null, projector = false, fit = false, lang = null,
} = {}) {
  const search = new URLSearchParams({ panel: panel.id });
  writeParams(panel.schema, { ...defaults(panel.schema), ...values }, search);
  if (lock.length) search.set('lock', lock.join(','));
  if (hide.length) search.set('hide', hide.join(','));
  if (theme) search.set('theme', theme);
  if (projector) search.set('projector', '1');
  if (fit) search.set('fit', '1');
  if (lang) search.set('lang', lang);
  return `${base}${base.includes('?') ? '&' : '?'}${search.toString().replace(/%2C/g, ',')}`;
}
