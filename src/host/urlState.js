// @ts-check
// Panel state in the page URL: read once at start, rewritten (replaceState, no history spam)
// a moment after each change, so a copied link always reproduces what is on screen.
import { readParams, writeParams } from './params.js';

/** @typedef {import('./panelContract.js').Schema} Schema */

/**
 * The values the page's link holds for `schema` (its keys after `prefix`), and what it could not use.
 * @param {Schema} schema
 */
export function readUrlState(schema, prefix = '') {
  return readParams(schema, new URLSearchParams(window.location.search), prefix);
}

/**
 * Returns write(values): coalesces rapid changes (slider drags) into one URL update.
 * @param {Schema} schema
 * @returns {(values: Readonly<import('./panelContract.js').Values>) => void}
 */
export function urlWriter(schema, prefix = '', delayMs = 150) {
  let timer = 0;
  return (values) => {
    clearTimeout(timer);
    timer = setTimeout(() => {
      const url = new URL(window.location.href);
      writeParams(schema, values, url.searchParams, prefix);
      window.history.replaceState(window.history.state, '', url);
    }, delayMs);
  };
}
