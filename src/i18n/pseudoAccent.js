// @ts-check
// The pseudo-locale's letters (scripts/pseudoLocale.js, and the class view's worker, which makes its
// own): a, c, e, i, n, o, u and y accented, the letters still readable, so that a word shown without
// accents inside the brackets came from somewhere other than the catalogue.

const PAIRS = 'aáeéiíoóuúyýcçnñAÁEÉIÍOÓUÚYÝCÇNÑ';
/** @type {Record<string, string>} */
const ACCENTS = Object.fromEntries(Array.from({ length: PAIRS.length / 2 }, (_, i) => [PAIRS[2 * i], PAIRS[2 * i + 1]]));

/**
 * Letters accented; markup tags (<sub>) and entities (&amp;) left alone.
 * @param {string} text
 */
export const accent = (text) => text.replace(/(<[^>]*>|&[a-z#0-9]+;)|([A-Za-z])/g,
  (_, tag, letter) => (tag ? tag : ACCENTS[letter] ?? letter));
