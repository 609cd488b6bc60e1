// @ts-check
// A panel's frame holds the lab's embed page, which says so at once (fresnel-lab:loading, before
// its panel's module arrives; src/embed.js). A frame that has loaded and said nothing holds
// something else: the browser's own error page, when embed.html is not beside the file that frames
// it (a lecture or sheet opened from disk, apart from the folder it came in). Then the page says so
// in its own words instead of leaving that error page inside the lecture.

/** How long a loaded frame has to speak before it is taken for one that could not load, in ms. */
export const FRAME_GRACE_MS = 5000;

/**
 * Calls onMissing() once when `frame` has loaded and no fresnel-lab: message came from it within
 * `grace` ms; nothing when one did. Returns a function that stops watching.
 * @param {HTMLIFrameElement} frame
 * @param {() => void} onMissing
 */
export function watchPanelFrame(frame, onMissing, { grace = FRAME_GRACE_MS } = {}) {
  let heard = false;
  let timer = 0;
  const stop = () => {
    clearTimeout(timer);
    window.removeEventListener('message', onMessage);
    frame.removeEventListener('load', onLoad);
  };
  /** @param {MessageEvent<unknown>} event */
  function onMessage(event) {
    const { data } = event;
    const type = typeof data === 'object' && data !== null && 'type' in data ? data.type : undefined;
    if (event.source !== frame.contentWindow || typeof type !== 'string' || !type.startsWith('fresnel-lab:')) return;
    heard = true;
    stop();
  }
  function onLoad() {
    clearTimeout(timer);
    timer = window.setTimeout(() => {
      if (heard || !frame.isConnected) return;
      stop();
      onMissing();
    }, grace);
  }
  window.addEventListener('message', onMessage);
  frame.addEventListener('load', onLoad);
  return stop;
}
