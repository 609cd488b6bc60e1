// @ts-check
// An element of the page's own markup (index.html, embed.html, homework.html, compose.html): it is
// always there in a page built from this project, so its absence is a build fault, named at once.

/**
 * The first element matching `selector` within `root` (the document by default).
 * @param {string} selector
 * @param {ParentNode} [root]
 * @returns {HTMLElement}
 */
export function pageElement(selector, root = document) {
  const found = root.querySelector(selector);
  if (!(found instanceof HTMLElement)) throw new Error(`The page has no ${selector}.`);
  return found;
}
