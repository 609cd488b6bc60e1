// @ts-check
// How a panel fits its frame on a slide (embed option fit=1; fitToFrame.js measures and applies):
// pure choices, testable in Node. A layout is a zoom (CSS zoom on the embed's root: type, plots
// and controls smaller alike), a number of columns the panel's parts flow in, and a cap on its
// pictures' height as a share of the frame's (a picture whose height follows its width does not
// get shorter with zoom: the root is wider in zoomed px by as much as it is smaller).
//
// Of the layouts that fit, the one chosen gives the text and the picture the most of what they
// need on a projector: a zoom of GOOD_ZOOM (16 px type) and a picture of GOOD_PICTURE of the
// frame's height count as enough; past the floor (MIN_TYPE_PX type) nothing is shrunk further,
// and a panel that still does not fit scrolls in its frame and says so.

/** The smallest root type a fitted panel shows, in CSS px of the frame: 12 px, its smallest labels about 9 px. */
export const MIN_TYPE_PX = 12;
/** Zooms are tried on steps of this size, from 1 down to the floor. */
export const ZOOM_STEP = 0.025;
/** Caps tried on a picture's height, as shares of the frame's height (besides none). */
export const PICTURE_SHARES = /** @type {const} */ ([0.6, 0.5, 0.4, 0.3]);
/** The most columns a panel's parts flow in. */
export const MAX_COLUMNS = 3;
/** A zoom at which type needs no more on a slide (16 px from the 20 px root). */
export const GOOD_ZOOM = 0.8;
/** A picture's height, as a share of the frame's, that needs no more. */
export const GOOD_PICTURE = 0.5;

/**
 * The smallest zoom for a root font of `rootPx` CSS px: type stays at MIN_TYPE_PX or more (a
 * projector mode's larger type may shrink further). Rounded up to a step.
 * @param {number} rootPx
 */
export function zoomFloor(rootPx) {
  if (!(rootPx > 0)) return 1;
  const raw = Math.min(1, MIN_TYPE_PX / rootPx);
  return Math.min(1, Math.round(Math.ceil(raw / ZOOM_STEP - 1e-9) * ZOOM_STEP * 1000) / 1000);
}

/**
 * The zooms to try, largest first: 1, 1 − ZOOM_STEP, … down to `floor`.
 * @param {number} floor
 */
export function zoomSteps(floor) {
  /** @type {number[]} */
  const steps = [];
  for (let i = 0; ; i += 1) {
    const zoom = Math.round((1 - i * ZOOM_STEP) * 1000) / 1000;
    if (zoom < floor - 1e-9) break;
    steps.push(zoom);
  }
  return steps;
}

/**
 * The largest of `steps` (largest first) at which `fits` holds, by bisection: content shrinks as
 * the zoom does, so past the first zoom that fits every smaller one fits too. null: none fits.
 * @param {readonly number[]} steps
 * @param {(zoom: number) => boolean} fits
 */
export function largestFitting(steps, fits) {
  if (!steps.length) return null;
  if (fits(steps[0])) return steps[0];
  let lo = 0; // does not fit
  let hi = steps.length - 1;
  if (!fits(steps[hi])) return null;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (fits(steps[mid])) hi = mid;
    else lo = mid;
  }
  return steps[hi];
}

/**
 * The layouts to try: each number of columns up to `columns` with no cap on the pictures, and
 * then each cap that is below the share of the frame the largest picture takes uncapped.
 * @param {{ columns: number, pictureShare: number | null }} panel  pictureShare: null where it has no picture
 * @returns {{ columns: number, share: number | null }[]}
 */
export function layoutCandidates({ columns, pictureShare }) {
  const most = Math.max(1, Math.min(MAX_COLUMNS, Math.floor(columns)));
  const shares = [null, ...(pictureShare === null ? [] : PICTURE_SHARES.filter((share) => share < pictureShare))];
  return shares.flatMap((share) => Array.from({ length: most }, (_, i) => ({ columns: i + 1, share })));
}

/**
 * @typedef {object} Fitted
 * @property {number} zoom
 * @property {number} columns
 * @property {number | null} share     the cap on the pictures' height, or null
 * @property {number | null} picture   the largest picture's height as a share of the frame's; null: none
 */

/**
 * How well a layout shows its panel: what the worse served of type and picture gets of what it
 * needs (each counted up to enough), then the zoom, then the picture, then fewer columns.
 * @param {Fitted} layout
 * @returns {number[]}
 */
export function layoutScore({ zoom, picture, columns }) {
  const type = Math.min(1, zoom / GOOD_ZOOM);
  const seen = picture === null ? 1 : Math.min(1, picture / GOOD_PICTURE);
  const round = (/** @type {number} */ x) => Math.round(x * 1000) / 1000;
  return [round(Math.min(type, seen)), round(zoom), round(picture ?? 0), -columns];
}

/**
 * Whether layout `a` shows its panel better than `b` (layoutScore, compared in order).
 * @param {Fitted} a @param {Fitted} b
 */
export function betterLayout(a, b) {
  const sa = layoutScore(a);
  const sb = layoutScore(b);
  for (let i = 0; i < sa.length; i += 1) if (sa[i] !== sb[i]) return sa[i] > sb[i];
  return false;
}

/** A panel that overflows its frame at the floor by no more than this share of the frame's height nearly fits. */
export const NEAR_FIT = 0.2;

/**
 * The layout of a panel that does not fit its frame with type at the floor, so scrolls in it: the
 * layout that overflows least, where that nearly fits; else one column read from the top, as on
 * the lecture page, with type at GOOD_ZOOM and the picture on no more than 60 % of the frame (more
 * columns would have the reader scroll down one and up again to the next).
 * @param {{ least: { layout: { zoom: number, columns: number, share: number | null }, over: number } | null,
 *   frame: number, floor: number, pictureShare: number | null }} measured
 */
export function scrollingLayout({ least, frame, floor, pictureShare }) {
  if (least && least.over <= NEAR_FIT * frame) return least.layout;
  const share = pictureShare !== null && pictureShare > PICTURE_SHARES[0] ? PICTURE_SHARES[0] : null;
  return { zoom: Math.max(floor, GOOD_ZOOM), columns: 1, share };
}
