// @ts-check
// Text written into HTML as text (files the lab writes: a deck, an offline lecture, an embed
// snippet; the pages' own words at build time): & < > " ' as entities, so no text can open a tag or
// end a quoted attribute. Pure, with no imports: the build (Node) uses it too.

const ENTITIES = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' };

/**
 * Text for an element's content or a quoted attribute value.
 * @param {unknown} text
 * @returns {string}
 */
export function escapeHtml(text) {
  return String(text).replace(/[&<>"']/g, (c) => ENTITIES[/** @type {keyof typeof ENTITIES} */ (c)]);
}
