// What a page in a pseudo-locale must not show (pseudoLocale.spec.js). Under ?lang=en-XA every
// catalogue message is accented, about 35 % longer and ⟦bracketed⟧ (scripts/pseudoLocale.js), so
// (a) letters outside brackets are words that never went through the catalogue, and (b) text that
// is cut, runs off the screen or lies on other text is a layout that does not take longer words
// (or, under ?lang=ar-XB, the other direction). Each finding is one line: the page, the element
// (its panel, tag and classes) and the text.

/**
 * Not read for (a): formulas, code and the GLSL editor (not words), canvases, form fields' own text,
 * a date or time as Intl writes it in the page's language (<time>), words set in a language of
 * their own (`lang` on the element: the language selector names each language in itself), and
 * words that come from outside the lab, which no catalogue holds: `data-pseudo-skip`, and
 * `outside`, the selectors a test names (a student's name, a lecturer's own heading and text).
 * A select's options are read: they are the lab's words.
 */
const NOT_WORDS = '.katex, code, pre, .cm-editor, script, style, canvas, textarea, time, [lang]:not(html), [data-pseudo-skip]';

/**
 * (a) also reads inside the brackets: a catalogue's word there is accented, so a word of plain
 * letters is an argument that never went through the catalogue (a material's English name), unless
 * it is one of `known`, the words a test brought in from outside.
 * Where (a) looks: every visible text node (read with its element's whole text, since a message's
 * brackets may sit in sibling nodes) and every attribute a reader hears or sees, plus `live`, the
 * texts the page's live regions said so far and the page's title. Needs pseudoAuditScript.
 * Returns findings, each { where, text }.
 */
export const wordsOutsideCatalogue = (page, { root = 'body', outside = [], known = [], live = true } = {}) => page.evaluate(({
  within, skip, isLive, knownWords,
}) => {
  const outsideBrackets = (text) => {
    let depth = 0;
    let rest = '';
    let inside = '';
    for (const ch of text) {
      if (ch === '⟦') depth += 1;
      else if (ch === '⟧') depth = Math.max(0, depth - 1);
      else if (!depth) rest += ch;
      else inside += ch;
    }
    // An English word inside the brackets came in as a message's argument, not from the catalogue:
    // the catalogue's words have every a, c, e, i, n, o, u and y accented (GLSL, km and px have none).
    const unaccented = inside.match(/(?<![\p{L}\p{N}_])[A-Za-z]*[aceinouyACEINOUY][A-Za-z]*(?![\p{L}\p{N}_])/gu)
      ?.filter((word) => word.length > 1 && !knownWords.includes(word)) ?? [];
    if (unaccented.length) rest += ` ${unaccented.join(' ')}`;
    // Two letters in a row are a word; one (θ, n, R) is a symbol.
    return /\p{L}{2,}/u.test(rest) ? rest.replace(/\s+/g, ' ').trim() : null;
  };
  const { where } = window.__pseudo;
  const found = new Map();
  const add = (kind, el, rest) => {
    const key = `${kind}: “${rest.slice(0, 100)}” in ${where(el)}`;
    if (!found.has(key)) found.set(key, { where: where(el), text: `${kind}: “${rest.slice(0, 100)}”` });
  };
  const roots = [...document.querySelectorAll(within)].filter((r, _, all) => !all.some((o) => o !== r && o.contains(r)));
  const shown = (el) => el.checkVisibility({ checkOpacity: true, checkVisibilityCSS: true }) && el.getClientRects().length > 0;
  // An element's own words: its text, less what is not read and the options of a select inside it.
  const wordsOf = (el) => {
    let text = '';
    const walker = document.createTreeWalker(el, NodeFilter.SHOW_ELEMENT | NodeFilter.SHOW_TEXT, (n) => {
      if (n.nodeType === Node.TEXT_NODE) return NodeFilter.FILTER_ACCEPT;
      return n !== el && (n.matches(skip) || n.matches('select')) ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_SKIP;
    });
    for (let n = walker.nextNode(); n; n = walker.nextNode()) text += n.data;
    return text;
  };
  for (const top of roots) {
    const walker = document.createTreeWalker(top, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const el = node.parentElement;
      if (!el || !/\p{L}/u.test(node.data) || el.closest(skip)) continue;
      const option = el.closest('option');
      if (!shown(option ? option.closest('select') ?? el : el)) continue;
      const rest = outsideBrackets(wordsOf(option ?? el));
      if (rest) add('text', option ?? el, rest);
    }
    // Words a style sheet writes (content: '…') are shown too, and no catalogue reaches them.
    for (const el of top.querySelectorAll('*')) {
      if (el.closest(skip)) continue;
      for (const pseudo of ['::before', '::after']) {
        const content = getComputedStyle(el, pseudo).content;
        const strings = content.startsWith('"') ? content.match(/"(?:[^"\\]|\\.)*"/g)?.map((q) => q.slice(1, -1)).join('') : '';
        const rest = strings && shown(el) ? outsideBrackets(strings) : null;
        if (rest) add(`${pseudo} content`, el, rest);
      }
    }
  }
  const ATTRIBUTES = ['aria-label', 'aria-description', 'aria-valuetext', 'aria-roledescription', 'title', 'placeholder', 'alt'];
  const labelled = roots.flatMap((r) => [...(r.matches(ATTRIBUTES.map((a) => `[${a}]`).join(', ')) ? [r] : []),
    ...r.querySelectorAll(ATTRIBUTES.map((a) => `[${a}]`).join(', '))]);
  for (const el of labelled) {
    if (el.closest(skip)) continue;
    for (const name of ATTRIBUTES) {
      const rest = el.hasAttribute(name) ? outsideBrackets(el.getAttribute(name)) : null;
      if (rest) add(name, el, rest);
    }
  }
  // <title> is read out first by a screen reader, and is the tab's name.
  const title = isLive ? outsideBrackets(document.title) : null;
  if (title) found.set(`title ${title}`, { where: 'title', text: `the page's title: “${title}”` });
  if (isLive) {
    for (const said of window.__pseudo.said) {
      const rest = outsideBrackets(said.text);
      if (rest) found.set(`live ${said.where} ${rest}`, { where: said.where, text: `said by a live region: “${rest.slice(0, 100)}”` });
    }
  }
  return [...found.values()];
}, { within: root, skip: [NOT_WORDS, ...outside].join(', '), isLive: live, knownWords: known });

/**
 * The init script every page of a pseudo-locale test needs (context.addInitScript): `where(el)`,
 * an element named by its panel, the shared part it sits in (the toolbar, controls, trace and fault
 * line every panel has, a notice, the page controls, a stability map's counts and legend) and its
 * tag and classes; and `said`, every text a
 * live region ([aria-live], role status, alert or log) was given, as a screen reader says it
 * (a line replaced at once is heard too).
 */
export function pseudoAuditScript() {
  const FRAME = ['.toolbar', '.lil-gui', '.trace', '.panel-fault', '.notice', '.page-controls', '.keys-help', '.site-header',
    '.site-footer', '.st-counts', '.st-legend'];
  const where = (el) => {
    const panel = el.closest('[data-panel]')?.getAttribute('data-panel');
    const frame = FRAME.find((selector) => el.parentElement?.closest(selector));
    const classes = typeof el.className === 'string' && el.className ? `.${el.className.trim().split(/\s+/).join('.')}` : '';
    return `${panel ? `[${panel}] ` : ''}${frame ? `${frame} › ` : ''}${el.tagName.toLowerCase()}${classes}`;
  };
  const said = [];
  window.__pseudo = { where, said };
  const LIVE = '[aria-live]:not([aria-live="off"]), [role="status"], [role="alert"], [role="log"]';
  const note = (el) => {
    const text = el.textContent.trim();
    if (!text || el.closest('.katex, [data-pseudo-skip]')) return;
    if (said.at(-1)?.text !== text) said.push({ where: where(el), text });
  };
  const observer = new MutationObserver((changes) => {
    const regions = new Set();
    for (const change of changes) {
      const target = change.target.nodeType === Node.ELEMENT_NODE ? change.target : change.target.parentElement;
      const region = target?.closest(LIVE);
      if (region) regions.add(region);
    }
    regions.forEach(note);
  });
  const start = () => observer.observe(document.documentElement, { subtree: true, childList: true, characterData: true });
  if (document.documentElement) start();
  else document.addEventListener('readystatechange', start, { once: true });
}

/**
 * (b): text that does not fit. For every visible text node: its line boxes must lie inside each
 * ancestor that clips (overflow hidden or clip; text-overflow: ellipsis needs one) and, unless a box
 * that scrolls holds it, inside the screen's width; and no two text nodes may share ground (more
 * than 2 px across and a third of the lower line's height), counting only the part of each that its
 * clipping and scrolling boxes leave in view. Text under a sticky or fixed bar is covered by the bar,
 * not written over. Formulas are left out (KaTeX stacks its glyphs by design). Needs
 * pseudoAuditScript. Returns findings { where, text }.
 */
export const textLayoutFaults = (page, { root = 'body' } = {}) => page.evaluate((within) => {
  const SKIP = '.katex, script, style, select, option, .sr-only, [data-pseudo-skip]';
  const width = document.documentElement.clientWidth;
  const { where } = window.__pseudo;
  const excerpt = (el) => el.textContent.replace(/\s+/g, ' ').trim().slice(0, 60);
  const found = new Map();
  const add = (el, what) => {
    const key = `${where(el)} ${what}`;
    if (!found.has(key)) found.set(key, { where: where(el), text: `${what}: “${excerpt(el)}”` });
  };
  if (document.documentElement.scrollWidth > width + 1) {
    found.set('page', { where: 'html', text: `the page is ${document.documentElement.scrollWidth} px wide on a ${width} px screen` });
  }
  const styles = new Map();
  const style = (el) => {
    if (!styles.has(el)) {
      const s = getComputedStyle(el);
      styles.set(el, {
        cuts: /hidden|clip/.test(s.overflowX) || /hidden|clip/.test(s.overflowY),
        cutsX: /hidden|clip/.test(s.overflowX), cutsY: /hidden|clip/.test(s.overflowY),
        scrolls: /auto|scroll/.test(s.overflowX) || /auto|scroll/.test(s.overflowY),
        bar: s.position === 'sticky' || s.position === 'fixed',
      });
    }
    return styles.get(el);
  };
  const roots = [...document.querySelectorAll(within)].filter((r, _, all) => !all.some((o) => o !== r && o.contains(r)));
  const nodes = roots.flatMap((top) => {
    const walker = document.createTreeWalker(top, NodeFilter.SHOW_TEXT);
    const all = [];
    for (let node = walker.nextNode(); node; node = walker.nextNode()) all.push(node);
    return all;
  });
  const boxes = [];
  for (const node of nodes) {
    const el = node.parentElement;
    if (!el || !node.data.trim() || el.closest(SKIP)) continue;
    if (!el.checkVisibility({ checkOpacity: true, checkVisibilityCSS: true })) continue;
    const range = document.createRange();
    range.selectNodeContents(node);
    let rects = [...range.getClientRects()].filter((r) => r.width > 0.5 && r.height > 0.5)
      .map((r) => ({ left: r.left, right: r.right, top: r.top, bottom: r.bottom }));
    if (!rects.length) continue;
    let inScroller = false;
    let cut = false;
    let bar = null;
    for (let a = el; a && a !== document.documentElement; a = a.parentElement) {
      const s = style(a);
      if (s.bar && !bar) bar = a;
      if (!s.cuts && !s.scrolls) continue;
      const box = a.getBoundingClientRect();
      // A box 2 px wide that clips holds a screen reader's text, not a cut one.
      if (s.cuts && (box.width <= 2 || box.height <= 2)) { rects = []; break; }
      const left = box.left + a.clientLeft;
      const top = box.top + a.clientTop;
      const inner = { left, right: left + a.clientWidth, top, bottom: top + a.clientHeight };
      if (s.scrolls) inScroller = true;
      else if (!cut) {
        const cutX = s.cutsX && rects.some((r) => r.left < inner.left - 1 || r.right > inner.right + 1);
        const cutY = s.cutsY && rects.some((r) => r.top < inner.top - 2 || r.bottom > inner.bottom + 2);
        if (cutX || cutY) {
          add(el, `cut by ${where(a)} (${cutX ? 'across' : 'down'})`);
          cut = true;
        }
      }
      // What this box leaves in view, for the overlaps below.
      rects = rects.map((r) => ({ left: Math.max(r.left, inner.left), right: Math.min(r.right, inner.right),
        top: Math.max(r.top, inner.top), bottom: Math.min(r.bottom, inner.bottom) }))
        .filter((r) => r.right - r.left > 0.5 && r.bottom - r.top > 0.5);
      if (!rects.length) break;
    }
    if (!inScroller && rects.some((r) => r.left < -1 || r.right > width + 1)) add(el, 'runs off the screen');
    for (const r of rects) boxes.push({ el, r, bar });
  }
  // Text on text: sorted by top, each box against those that start above its bottom.
  boxes.sort((p, q) => p.r.top - q.r.top);
  for (let i = 0; i < boxes.length; i += 1) {
    const { el, r, bar } = boxes[i];
    for (let j = i + 1; j < boxes.length && boxes[j].r.top < r.bottom; j += 1) {
      const other = boxes[j];
      if (other.el === el || other.bar !== bar) continue;
      const across = Math.min(r.right, other.r.right) - Math.max(r.left, other.r.left);
      const down = Math.min(r.bottom, other.r.bottom) - Math.max(r.top, other.r.top);
      if (across > 2 && down > Math.min(r.bottom - r.top, other.r.bottom - other.r.top) / 3) {
        add(el, `lies on ${where(other.el)} “${excerpt(other.el).slice(0, 30)}”`);
      }
    }
  }
  return [...found.values()];
}, root);

/**
 * What must not mirror right to left (a picture, a plot, a formula, code): each element matching
 * one of `selectors` whose direction is not ltr, as findings { where, text }.
 */
export const mirroredGeometry = (page, selectors) => page.evaluate((list) => list.flatMap((selector) => {
  const turned = [...document.querySelectorAll(selector)].filter((e) => getComputedStyle(e).direction !== 'ltr');
  return turned.length ? [{ where: selector, text: `mirrored: ${turned.length} × ${selector} lays out right to left` }] : [];
}), selectors);
