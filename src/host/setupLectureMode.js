// @ts-check
// Lecture mode: a clicker or the keyboard steps panel to panel (arrows, Page Up/Down, Space),
// `f` toggles full screen, `h` hides every control; the current panel is kept in the URL hash so
// a reload returns to it.
const NEXT = new Set(['ArrowDown', 'ArrowRight', 'PageDown', ' ']);
const PREVIOUS = new Set(['ArrowUp', 'ArrowLeft', 'PageUp']);

/**
 * Keys typed into a form control, or given to a focused canvas or slider, are not navigation.
 * @param {EventTarget | null} target
 */
function ownsKeys(target) {
  if (!(target instanceof Element)) return false;
  return Boolean(target.closest('input, select, textarea, button, a, canvas, [contenteditable], [role="slider"], .lil-gui, table'));
}

/**
 * Lecture mode over the page's panel sections, in order. onHideControls: the `h` key.
 * @param {HTMLElement[]} sections
 * @param {{ onHideControls?: () => void }} [options]
 */
export function setupLectureMode(sections, { onHideControls } = {}) {
  let current = Math.max(0, sections.findIndex((s) => `#${s.id}` === window.location.hash));

  const goTo = (/** @type {number} */ index) => {
    current = Math.min(sections.length - 1, Math.max(0, index));
    const section = sections[current];
    section.scrollIntoView({ behavior: 'auto', block: 'start' });
    section.focus({ preventScroll: true });
    setHash(section.id);
  };
  const setHash = (/** @type {string} */ id) => {
    if (window.location.hash !== `#${id}`) window.history.replaceState(window.history.state, '', `#${id}`);
  };

  // The current panel is the one nearest the top of the screen.
  const observer = new IntersectionObserver(() => {
    let best = current;
    let bestDistance = Infinity;
    sections.forEach((s, i) => {
      const d = Math.abs(s.getBoundingClientRect().top);
      if (d < bestDistance) { best = i; bestDistance = d; }
    });
    if (best !== current) {
      current = best;
      setHash(sections[current].id);
    }
  }, { threshold: [0, 0.25, 0.5, 0.75, 1] });
  sections.forEach((s) => observer.observe(s));

  /** @param {KeyboardEvent} event */
  const onKey = (event) => {
    if (event.defaultPrevented || event.ctrlKey || event.metaKey || event.altKey) return;
    if (ownsKeys(event.target)) return;
    if (NEXT.has(event.key) && !(event.key === ' ' && event.shiftKey)) {
      event.preventDefault();
      goTo(current + 1);
    } else if (PREVIOUS.has(event.key) || (event.key === ' ' && event.shiftKey)) {
      event.preventDefault();
      goTo(current - 1);
    } else if (event.key === 'f') {
      toggleFullscreen();
    } else if (event.key === 'h') {
      onHideControls?.();
    }
  };
  document.addEventListener('keydown', onKey);

  const api = {
    goTo,
    get current() { return current; },
    /** Keeps the panel named in the hash at the top while the panels around it mount and change
     *  height (until `settled` resolves, and a moment after), unless the reader scrolls or types:
     *  a reload returns to the panel, not near it. */
    holdHashTarget(settled = Promise.resolve(), afterMs = 1500) {
      const target = window.location.hash && sections.find((s) => `#${s.id}` === window.location.hash);
      if (!target) return;
      const place = () => target.scrollIntoView({ block: 'start' });
      place();
      const resize = new ResizeObserver(place);
      resize.observe(document.querySelector('main') ?? document.body);
      const events = ['wheel', 'keydown', 'touchstart', 'pointerdown'];
      const stop = () => {
        resize.disconnect();
        for (const type of events) window.removeEventListener(type, stop, true);
      };
      for (const type of events) window.addEventListener(type, stop, true);
      settled.finally(() => setTimeout(stop, afterMs));
    },
  };
  // A link to #panel within the page: the browser jumps there; hold it while the panels near it mount.
  window.addEventListener('hashchange', () => {
    const index = sections.findIndex((s) => `#${s.id}` === window.location.hash);
    if (index < 0) return;
    current = index;
    api.holdHashTarget();
  });
  return api;
}

export function toggleFullscreen() {
  if (document.fullscreenElement) document.exitFullscreen?.();
  else document.documentElement.requestFullscreen?.().catch(() => {});
}
