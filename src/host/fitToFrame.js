// @ts-check
// A panel on a slide shows whole in its frame (embed option fit=1), as large as it can: its
// pictures take their height from the frame, its parts may flow in columns beside each other where
// the frame is wide, and the embed's root is zoomed down (CSS zoom: type, plots and canvases alike,
// pointer positions kept; layout, hit testing and getBoundingClientRect agree, CSS Viewport Module
// Level 1, "zoom"). fitLayout.js chooses among the layouts that fit; this module tries them on the
// page, one layout pass each, and keeps the best. Type never shrinks below fitLayout's floor: a
// panel that still does not fit scrolls inside its frame, and a cue at the frame's foot says so.
import { betterLayout, largestFitting, layoutCandidates, scrollingLayout, zoomFloor, zoomSteps } from './fitLayout.js';
import './fitToFrame.css';

/** Overflow of no more than this many px is rounding, not content cut off. */
const SLACK_PX = 1;

/**
 * Whether `node` is a box whose children columns may take: a block, grid or flex container that
 * neither scrolls nor is a table or a picture.
 * @param {Element} node
 */
function mayFlow(node) {
  const style = getComputedStyle(node);
  return node instanceof HTMLElement && /^(block|flow-root|grid|flex)$/.test(style.display) && style.overflowX === 'visible'
    && style.overflowY === 'visible' && style.aspectRatio === 'auto';
}

/**
 * The element whose children are the panel's parts: the first below `content` with more than one
 * child shown, if columns may take them; else none.
 * @param {Element | null} content
 */
function findFlow(content) {
  let node = content;
  while (node && mayFlow(node)) {
    const shown = [...node.children].filter((child) => child.getClientRects().length);
    if (shown.length !== 1) return shown.length ? node : null;
    node = shown[0];
  }
  return null;
}

/**
 * A picture whose height follows its width: a box given an aspect-ratio by its CSS (not the
 * `auto w / h` a canvas or image takes from its size attributes: a plot's canvas has its own
 * height), or an SVG drawn from its viewBox at the width it is given (not a formula's brackets).
 * @param {Element} node
 */
function isPicture(node) {
  const ratio = getComputedStyle(node).aspectRatio;
  if (ratio !== 'auto' && !ratio.startsWith('auto ')) return true;
  return node instanceof SVGSVGElement && node.hasAttribute('viewBox') && !node.closest('.katex');
}

/** @param {Element} content */
function findPictures(content) {
  /** @type {HTMLElement[]} */
  const found = [];
  const walk = (/** @type {Element} */ node) => {
    for (const child of node.children) {
      if (!child.getClientRects().length) continue;
      if (isPicture(child) && (child instanceof HTMLElement || child instanceof SVGElement)) found.push(/** @type {HTMLElement} */ (child));
      else walk(child);
    }
  };
  walk(content);
  return found;
}

/**
 * @typedef {import('./fitLayout.js').Fitted & { scrolls: boolean }} FitState
 */

/**
 * Keeps the panel in `root` fitted to the window (its frame) as both change: at first, when the
 * frame is resized, and when its content grows past the frame. Returns the layout in force and a
 * function that stops it.
 * @param {HTMLElement} root
 * @param {{ moreBelow: string }} words  the cue's text, in the embed's language
 */
export function fitToFrame(root, { moreBelow }) {
  document.documentElement.classList.add('fit');
  /** @type {FitState} */
  let state = { zoom: 1, columns: 1, share: null, picture: null, scrolls: false };
  let searches = 0;
  let searchMs = 0; // how long the last search took
  let searchedHeight = 0; // the page's height when the layout was chosen
  let scheduled = 0;
  let fresh = true; // search again from full size: at first, and when the frame is resized
  /** @type {Element | null} */
  let flow = null;
  /** @type {{ node: HTMLElement, ratio: number }[]} */
  let pictures = [];

  const cue = document.createElement('button');
  cue.type = 'button';
  cue.className = 'fit-cue';
  cue.textContent = moreBelow;
  cue.hidden = true;
  cue.addEventListener('click', () => {
    const still = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches;
    window.scrollBy({ top: window.innerHeight * 0.8, behavior: still ? 'auto' : 'smooth' });
  });
  document.body.append(cue);

  /** @type {{ box: Element, over: number }[]} */
  let boxes = []; // boxes that scroll sideways (a wide table, code), and by how much they did at full size
  const overflow = () => document.documentElement.scrollHeight - window.innerHeight;
  const sidewaysOver = (/** @type {Element} */ box) => Math.max(0, box.scrollWidth - box.clientWidth);
  // No box hides more sideways than at full size, but one that scrolled then may hide a twentieth of its width more.
  const sideways = () => boxes.every(({ box, over }) => sidewaysOver(box) <= (over > SLACK_PX ? over + box.clientWidth / 20 : SLACK_PX));
  // A layout fits when the page needs no scrolling and no box scrolls sideways further.
  const fits = () => overflow() <= SLACK_PX && sideways();
  const atEnd = () => window.scrollY + window.innerHeight >= document.documentElement.scrollHeight - SLACK_PX;
  const showCue = () => { cue.hidden = !state.scrolls || atEnd(); };

  /** @param {{ zoom: number, columns: number, share: number | null }} layout */
  const apply = ({ zoom, columns, share }) => {
    root.style.zoom = String(zoom);
    if (flow instanceof HTMLElement) {
      flow.classList.toggle('fit-columns', columns > 1);
      flow.style.columnCount = columns > 1 ? String(columns) : '';
    }
    const cap = share === null ? null : (share * window.innerHeight) / zoom; // in the root's zoomed px
    for (const { node, ratio } of pictures) {
      node.classList.toggle('fit-picture', cap !== null);
      node.style.maxWidth = cap === null ? '' : `${Math.floor(cap * ratio)}px`;
    }
  };
  const tallestPicture = () => Math.max(0, ...pictures.map(({ node }) => node.getBoundingClientRect().height)) / window.innerHeight;

  const search = () => {
    searches += 1;
    const started = performance.now();
    try {
      searchOnce();
    } finally {
      searchMs = performance.now() - started;
    }
  };
  const searchOnce = () => {
    apply({ zoom: 1, columns: 1, share: null }); // the last search's flow and pictures back to full size
    for (const { node } of pictures) node.classList.remove('fit-span');
    for (const part of flow?.children ?? []) part.classList.remove('fit-breaks');
    const content = root.querySelector('.panel-content');
    flow = findFlow(content);
    pictures = content ? findPictures(content).map((node) => {
      const { width, height } = node.getBoundingClientRect();
      return { node, ratio: height > 0 ? width / height : 1 };
    }).filter(({ ratio }) => ratio > 0) : [];
    const picture = pictures.length ? tallestPicture() : null;
    boxes = content ? [...content.querySelectorAll('*')].filter((node) => /auto|scroll/.test(getComputedStyle(node).overflowX)
      && node.getClientRects().length).map((box) => ({ box, over: sidewaysOver(box) })) : [];
    state = { zoom: 1, columns: 1, share: null, picture, scrolls: false };
    searchedHeight = document.documentElement.scrollHeight;
    if (overflow() <= SLACK_PX) return;
    // A picture that is one of the parts spans all columns: the other parts flow below it. A part
    // taller than the frame may break between columns; the others stay whole.
    for (const { node } of pictures) if (node.parentElement === flow) node.classList.add('fit-span');
    const parts = [...flow?.children ?? []].filter((part) => part.getClientRects().length && !part.classList.contains('fit-span'));
    for (const part of parts) part.classList.toggle('fit-breaks', part.getBoundingClientRect().height > window.innerHeight);
    const steps = zoomSteps(zoomFloor(Number.parseFloat(getComputedStyle(document.documentElement).fontSize)));
    /** @type {import('./fitLayout.js').Fitted | null} */
    let best = null;
    /** @type {{ layout: { zoom: number, columns: number, share: number | null }, over: number } | null} */
    let least = null;
    for (const candidate of layoutCandidates({ columns: parts.length, pictureShare: picture })) {
      const zoom = largestFitting(steps, (z) => {
        apply({ ...candidate, zoom: z });
        return fits();
      });
      if (zoom === null) {
        const over = overflow(); // at the floor, where the search ended
        if (sideways() && (!least || over < least.over)) least = { layout: { ...candidate, zoom: steps.at(-1) ?? 1 }, over };
        continue;
      }
      apply({ ...candidate, zoom });
      const fitted = { ...candidate, zoom, picture: pictures.length ? tallestPicture() : null };
      if (!best || betterLayout(fitted, best)) best = fitted;
    }
    const chosen = best ?? scrollingLayout({ least, frame: window.innerHeight, floor: steps.at(-1) ?? 1, pictureShare: picture });
    apply(chosen);
    state = { ...chosen, picture: pictures.length ? tallestPicture() : null, scrolls: !best };
    searchedHeight = document.documentElement.scrollHeight;
  };

  const fit = () => {
    scheduled = 0;
    // Content that later shrinks keeps its layout until the frame is resized (growing back on
    // every shrink could swing between two layouts); content that grows past the frame is fitted again.
    // A panel that scrolls is fitted again only when its content has grown by a twentieth of the frame.
    const grown = state.scrolls ? document.documentElement.scrollHeight > searchedHeight + window.innerHeight / 20 : overflow() > SLACK_PX;
    if (fresh || grown) {
      fresh = false;
      search();
    }
    showCue();
  };
  const schedule = () => { if (!scheduled) scheduled = requestAnimationFrame(fit); };
  const onResize = () => { fresh = true; schedule(); };
  const observer = new ResizeObserver(schedule);
  observer.observe(root);
  window.addEventListener('resize', onResize);
  window.addEventListener('scroll', showCue, { passive: true });
  // A web font arriving (KaTeX's) changes the widths of what was measured in a fallback font.
  document.fonts?.addEventListener('loadingdone', onResize);
  schedule();
  return {
    /** The layout in force (zoom, columns, picture cap), and whether the panel scrolls. */
    get layout() { return { ...state, searches, searchMs }; },
    stop() {
      cancelAnimationFrame(scheduled);
      observer.disconnect();
      window.removeEventListener('resize', onResize);
      window.removeEventListener('scroll', showCue);
      document.fonts?.removeEventListener('loadingdone', onResize);
      cue.remove();
    },
  };
}
