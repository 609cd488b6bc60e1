// A panel's lede and citation in the page's language (markup as the catalogue's "panels" namespace
// has it: richText.js), apart from its title (panelText.js): the lecture page's own sections have
// them written by the build, so only a composed lecture and the composer bring these.
import english from 'virtual:messages/en/panels:lede+cite';
import { messages } from '../i18n/messages.js';
import { panelTitle, panelTitleHtml } from './panelText.js';

const t = messages('panels', english);

/** The lede (markup) under the heading. */
export const panelLede = (/** @type {string} */ id) => t(`${id}.lede`);

/** Where in the lecture, or beyond it, the concept comes from (markup). */
export const panelCite = (/** @type {string} */ id) => t(`${id}.cite`);

/** All four, as sectionHtml takes them. */
/** @param {string} id */
export const panelText = (id) => ({ title: panelTitle(id), titleHtml: panelTitleHtml(id), lede: panelLede(id), cite: panelCite(id) });
