// @ts-check
// KaTeX's stylesheet with its fonts inside, for a deck file that must show math as the site does
// (KaTeX's HTML, with its own fonts) wherever it is opened, from disk and offline too. A browser's
// own MathML rendering needs a math font the machine may lack: without one, \left( \right) do not
// stretch round a fraction and accents sit off-centre. Loaded with the deck's export only.
import katexCss from 'katex/dist/katex.min.css?raw';

// Each WOFF2 font as a data: URL (vite's ?inline); browsers that run WebGL2 all read WOFF2.
const fonts = import.meta.glob('/node_modules/katex/dist/fonts/*.woff2', { query: '?inline', import: 'default', eager: true });
const byName = Object.fromEntries(Object.entries(fonts).map(([path, url]) => [path.split('/').pop(), url]));

/** KaTeX's CSS with every font as WOFF2 only, inside it: the other formats' url()s are dropped. */
export function katexDeckCss() {
  return katexCss.replace(/src:([^;}]*)/g, (_whole, sources) => {
    const woff2 = /url\(fonts\/([^)]+\.woff2)\)/.exec(sources);
    return woff2 && byName[woff2[1]] ? `src:url(${byName[woff2[1]]}) format("woff2")` : `src:${sources}`;
  });
}
