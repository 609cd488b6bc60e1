// A panel's words in the page's language, from the catalogue's "panels" namespace (the manifest,
// src/panels/manifest.js, holds what is not words): its title as plain text and its title with
// markup for a heading, which every page shows. Its lede and its citation, which only a lecture the
// page composes or the composer writes, are panelLede.js's; the names of its controls, controlText.js's.
import english from 'virtual:messages/en/panels:title+titleHtml';
import { messages } from '../i18n/messages.js';
import { plainText } from '../i18n/richText.js';

const t = messages('panels', english);
const has = (/** @type {string} */ key) => Object.hasOwn(english, key);

/** Plain text: the embed heading, window titles, the controls' title. */
export const panelTitle = (/** @type {string} */ id) => plainText(t(`${id}.title`));

/** The heading with its markup (n<sub>t</sub>), where the catalogue has one; else the title. */
export const panelTitleHtml = (/** @type {string} */ id) => (has(`${id}.titleHtml`) ? t(`${id}.titleHtml`) : t(`${id}.title`));
