// KaTeX itself, in a chunk of its own (with its CSS): tex.js loads it once the panel's picture is up.
import katex from 'katex';
import 'katex/dist/katex.min.css';
import { patchTree } from './patchTree.js';

/**
 * Typesets TeX into an element. Errors show as red source text, never throw. A formula whose
 * numbers changed but whose shape did not (the live formulas of the panels, with fixed decimals)
 * is built aside and patched into the nodes already shown.
 * @param {HTMLElement} element
 * @param {string} tex
 * @param {boolean} display
 */
export function typesetTex(element, tex, display) {
  /** @type {import('katex').KatexOptions} */
  const options = { displayMode: display, throwOnError: false, output: 'htmlAndMathml' };
  if (element.firstElementChild?.classList.contains('katex') || element.firstElementChild?.classList.contains('katex-display')) {
    const fresh = document.createElement(element.tagName);
    katex.render(tex, fresh, options);
    if (!patchTree(element, fresh)) element.replaceChildren(...fresh.childNodes); // another shape: the new nodes as built
    return;
  }
  katex.render(tex, element, options);
}
