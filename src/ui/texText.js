// @ts-check
// Words inside a formula, set by KaTeX as text: a catalogue's words, in the page's language.

/** TeX's text-mode spelling of the characters TeX reads as commands (KaTeX reads ⟦ ⟧ as math-only ones). */
const TEXT_ESCAPES = /** @type {Readonly<Record<string, string>>} */ ({
  '\\': '\\textbackslash{}', '{': '\\{', '}': '\\}', $: '\\$', '&': '\\&', '#': '\\#', _: '\\_', '%': '\\%',
  '^': '\\textasciicircum{}', '~': '\\textasciitilde{}', '⟦': '$\\llbracket$', '⟧': '$\\rrbracket$',
});

/**
 * Words for a formula's \text{…} (a catalogue's, in the page's language), each character TeX
 * would read as a command spelled as text.
 * @param {string} words
 */
export const texText = (words) => words.replace(/[\\{}$&#_%^~⟦⟧]/g, (c) => TEXT_ESCAPES[c]);
