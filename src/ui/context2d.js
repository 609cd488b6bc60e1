// A canvas has one kind of context for life, fixed by the first getContext call. A 2D canvas whose
// context is first asked for when its first picture comes (once a worker's chains or a GPU's map
// arrive) can meanwhile be taken by a WebGL request (a page or a test that probes every canvas for
// its WebGL context to lose it), and then has no 2D context: drawing threw "Cannot set properties
// of null (setting 'fillStyle')". Claimed when the canvas is made, it stays 2D.

/**
 * The canvas's 2D context, claimed now; null only where the canvas already has another kind, in
 * which case its drawings are skipped rather than thrown.
 * @param {HTMLCanvasElement} canvas
 * @returns {CanvasRenderingContext2D | null}
 */
export function context2d(canvas) {
  return /** @type {CanvasRenderingContext2D | null} */ (canvas.getContext('2d'));
}
