// @ts-check
// A panel on a slide shows whole, without scrolling inside its frame (embed option fit=1): the
// embed's root is scaled down with CSS zoom, which lays the panel out smaller (type, plots and
// canvases alike, pointer positions kept) until its content fits the frame's height. zoom rather
// than a transform, so that layout, hit testing and getBoundingClientRect agree (CSS Viewport
// Module Level 1, "zoom"; Chrome 128+, Firefox 126+, Safari). Never below MIN_ZOOM: past that the
// frame scrolls rather than shrink type out of reach.

export const MIN_ZOOM = 0.4;

/**
 * The next zoom for content of height `needed` (measured at zoom `current`) in a frame of height
 * `available`: smaller in proportion while it overflows (content shrinks at least that much, since
 * narrower type rewraps into fewer lines, so a step or two reach it), else unchanged.
 * @param {number} needed @param {number} available @param {number} current
 */
export function shrunkZoom(needed, available, current) {
  if (!(needed > available + 1) || !(available > 0)) return current;
  return Math.max(MIN_ZOOM, Math.floor(current * (available / needed) * 1000) / 1000);
}

/**
 * Keeps `root` zoomed to fit the window's height as both change. Returns a function that stops it.
 * @param {HTMLElement} root
 */
export function fitToFrame(root) {
  let zoom = 1;
  let scheduled = 0;
  let fresh = true; // start again from full size: at first, and when the frame is resized
  const apply = (/** @type {number} */ value) => { zoom = value; root.style.zoom = String(value); };
  const fit = () => {
    scheduled = 0;
    if (fresh) {
      fresh = false;
      apply(1);
      schedule();
      return;
    }
    // The page's whole height, margins included; content that later shrinks keeps its zoom until
    // the frame is resized (growing back on every shrink could swing between two sizes).
    const needed = document.documentElement.scrollHeight;
    const available = window.innerHeight;
    const next = shrunkZoom(needed, available, zoom);
    if (next === zoom) return;
    apply(next);
    schedule();
  };
  const schedule = () => { if (!scheduled) scheduled = requestAnimationFrame(fit); };
  const onResize = () => { fresh = true; schedule(); };
  const observer = new ResizeObserver(schedule);
  observer.observe(root);
  window.addEventListener('resize', onResize);
  schedule();
  return () => {
    cancelAnimationFrame(scheduled);
    observer.disconnect();
    window.removeEventListener('resize', onResize);
  };
}
