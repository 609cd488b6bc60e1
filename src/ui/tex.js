// Formulas typeset with KaTeX (bundled; no CDN). Live numbers are best shown with a fixed number
// of decimals (toFixed) so a formula keeps its width as sliders move.
import katex from 'katex';
import 'katex/dist/katex.min.css';

/** Typesets TeX into an element (display style by default). Errors show as red source text, never throw. */
export function renderTex(element, tex, { display = true } = {}) {
  katex.render(tex, element, { displayMode: display, throwOnError: false, output: 'htmlAndMathml' });
  return element;
}

/** A new element holding typeset TeX. */
export function texElement(tex, { display = true, tag = 'div', className = 'tex' } = {}) {
  const element = document.createElement(tag);
  element.className = className;
  return renderTex(element, tex, { display });
}

/** A number for TeX with fixed decimals (in TeX's math mode a hyphen is typeset as the minus sign). */
export function texNumber(value, digits = 4) {
  if (!Number.isFinite(value)) return '\\text{—}';
  return value.toFixed(digits);
}
