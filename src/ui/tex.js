// Formulas typeset with KaTeX (bundled; no CDN). KaTeX is the largest library a panel uses, and
// a formula matters less in the first second than the picture and the numbers: it is fetched
// when the page is next idle after the first formula is asked for, and until it arrives each
// formula shows its TeX source. Live numbers are best shown with a fixed number of decimals
// (toFixed) so a formula keeps its width as sliders move.
import { shownDecimal } from './format.js';

/** @type {null | ((element: HTMLElement, tex: string, display: boolean) => void)} */
let typeset = null;
/** @type {Promise<void> | null} */
let loading = null;
/** @type {Map<HTMLElement, { tex: string, display: boolean }>} Elements waiting for KaTeX, with the latest TeX asked for each. */
const waiting = new Map();

/** Resolves once KaTeX is here (a test or an export can wait for typeset formulas). */
export function texReady() {
  loading ??= new Promise((resolve) => {
    const start = () => resolve(import('./typesetTex.js'));
    if (typeof requestIdleCallback === 'function') requestIdleCallback(start, { timeout: 300 });
    else setTimeout(start, 0);
  }).then((module) => {
    const { typesetTex } = /** @type {typeof import('./typesetTex.js')} */ (module);
    typeset = typesetTex;
    for (const [element, { tex, display }] of waiting) {
      element.removeAttribute('aria-busy');
      typesetTex(element, tex, display);
    }
    waiting.clear();
  });
  return loading;
}

/**
 * Typesets TeX into an element (display style by default); never throws.
 * @template {HTMLElement} E
 * @param {E} element
 * @param {string} tex
 * @param {{ display?: boolean }} [options]
 * @returns {E}
 */
export function renderTex(element, tex, { display = true } = {}) {
  if (typeset) {
    typeset(element, tex, display);
    return element;
  }
  waiting.set(element, { tex, display });
  element.textContent = tex;
  element.setAttribute('aria-busy', 'true');
  texReady();
  return element;
}

/**
 * A new element holding typeset TeX.
 * @param {string} tex
 * @param {{ display?: boolean, tag?: string, className?: string }} [options]
 */
export function texElement(tex, { display = true, tag = 'div', className = 'tex' } = {}) {
  const element = document.createElement(tag);
  element.className = className;
  return renderTex(element, tex, { display });
}

/**
 * A number for TeX with fixed decimals (in TeX's math mode a hyphen is typeset as the minus sign),
 * its decimal separator the page's: a comma as {,}, which TeX sets with no space after it.
 * @param {number} value
 */
export function texNumber(value, digits = 4) {
  if (!Number.isFinite(value)) return '\\text{—}';
  const text = value.toFixed(digits);
  const separator = shownDecimal();
  return separator === '.' ? text : text.replace('.', separator === ',' ? '{,}' : separator);
}
