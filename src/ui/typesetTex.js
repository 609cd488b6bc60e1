// KaTeX itself, in a chunk of its own (with its CSS): tex.js loads it once the panel's picture is up.
import katex from 'katex';
import 'katex/dist/katex.min.css';

/** Typesets TeX into an element. Errors show as red source text, never throw. */
export function typesetTex(element, tex, display) {
  katex.render(tex, element, { displayMode: display, throwOnError: false, output: 'htmlAndMathml' });
}
