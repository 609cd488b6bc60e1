// A panel's words in the page's language, from the catalogue's "panels" namespace (the manifest,
// src/panels/manifest.js, holds what is not words): its title as plain text and its title with
// markup for a heading; and from its "controls" namespace the names of its controls and of their
// options (`<panel>.<key>`, `<panel>.<key>.<value>`), which come with the page, before any panel's
// module, since a notice about a value in the link names its control. Its lede and its citation,
// which only a lecture the page composes or the composer writes, are panelLede.js's.
import english from 'virtual:messages/en/panels:title+titleHtml';
import controlWords from 'virtual:messages/en/controls';
import { messages } from '../i18n/messages.js';
import { plainText } from '../i18n/richText.js';

const t = messages('panels', english);
const controls = messages('controls', controlWords);
const has = (/** @type {string} */ key) => Object.hasOwn(english, key);

/** Plain text: the embed heading, window titles, the controls' title. */
export const panelTitle = (/** @type {string} */ id) => plainText(t(`${id}.title`));

/** The heading with its markup (n<sub>t</sub>), where the catalogue has one; else the title. */
export const panelTitleHtml = (/** @type {string} */ id) => (has(`${id}.titleHtml`) ? t(`${id}.titleHtml`) : t(`${id}.title`));

/** The name of a panel's control (a schema key), in the page's language. */
export const controlLabel = (/** @type {string} */ id, /** @type {string} */ key) => controls(`${id}.${key}`);

/**
 * The name an enum control shows for one of its values: its own words where the catalogue has
 * them, else the value itself (a size, a number of taps).
 * @param {string} id
 * @param {string} key
 * @param {unknown} value
 */
export function optionLabel(id, key, value) {
  const path = `${id}.${key}.${value}`;
  return Object.hasOwn(controlWords, path) ? controls(path) : String(value);
}
