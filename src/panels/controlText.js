// The names of a panel's controls and of their options (`<panel>.<key>`, `<panel>.<key>.<value>`)
// in the page's language, from the catalogue's "controls" namespace. They come with the panel host
// (its controls, and a notice about a value in the link, name them before any panel's module is
// here) and with the composer's start-state editor; a page that shows no controls (the homework
// page) does not load them. The panels' titles are panelText.js's.
import controlWords from 'virtual:messages/en/controls';
import { messages } from '../i18n/messages.js';

const controls = messages('controls', controlWords);

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
