// For the tests of a panel in the pseudo-locale (?lang=en-XA: every message of the catalogue
// accented and ⟦bracketed⟧, scripts/pseudoLocale.js): the words a panel shows outside the brackets,
// which are words that never came from the catalogue. Its own part of the page (what mount() made,
// the folders and names of its controls, its description), visible text and what a screen reader
// reads alike; formulas (KaTeX, and their TeX while KaTeX loads: aria-busy) and canvases are left
// out, as are the lecture note's label and the controls' title, which the frame around the panel writes.
import { labReady } from './fixtures.js';

/** The words (two letters or more) outside ⟦…⟧ in an embed's panel, each with where it was found. */
export function panelWordsOutside(page) {
  return page.evaluate(() => {
    const outside = (text) => {
      let depth = 0;
      let out = '';
      for (const ch of text) {
        if (ch === '⟦') depth += 1;
        else if (ch === '⟧') depth = Math.max(0, depth - 1);
        else out += depth ? ' ' : ch;
      }
      return (out.match(/\p{L}{2,}/gu) ?? []).join(' ');
    };
    const SKIP = '.katex, [aria-busy="true"], canvas, .lecture-note-label, .gui-host > .lil-gui > .lil-title';
    const roots = [...document.querySelectorAll('.panel-content, .gui-host .lil-gui .lil-children, .panel-description')];
    const found = new Set();
    for (const root of roots) {
      const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
      for (let node = walker.nextNode(); node; node = walker.nextNode()) {
        const parent = node.parentElement;
        if (!node.textContent.trim() || !parent || parent.closest(SKIP) || !parent.getClientRects().length) continue;
        // The parent's whole text: a message split by markup (n<sub>t</sub>) has its brackets in sibling nodes.
        const words = outside(parent.textContent);
        if (words) found.add(`${parent.localName}.${parent.getAttribute('class') ?? ''}: ${words}`);
      }
      for (const element of [root, ...root.querySelectorAll('*')]) {
        if (element.closest(SKIP) && element.localName !== 'canvas') continue;
        for (const name of ['aria-label', 'aria-valuetext', 'aria-description', 'title']) {
          if (name === 'aria-label' && element.matches('aside.lecture-note')) continue;
          const words = element.hasAttribute(name) ? outside(element.getAttribute(name)) : '';
          if (words) found.add(`${element.localName}[${name}]: ${words}`);
        }
      }
    }
    return [...found];
  });
}

/** Opens `path` in the pseudo-locale and waits for its panels (labReady: after its catalogue). */
export async function openInPseudoLocale(page, path) {
  await page.goto(`${path}${path.includes('?') ? '&' : '?'}lang=en-XA`);
  await labReady(page);
}
