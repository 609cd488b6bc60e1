// @ts-check
// Mount on approach, dispose when far: only panels on or near the screen hold a view, and never
// more than maxLive WebGL panels at once (the farthest one gives its context up first).
// Panels without WebGL stay mounted once they have been seen. A panel's module is fetched when the
// panel first comes near (so the page downloads only what is about to be seen); it mounts when
// the module arrives, if it is still near.
import { MAX_LIVE_CONTEXTS } from '../gl/contextBudget.js';

/**
 * A panel of the page: its section and its host.
 * @typedef {{ section: HTMLElement, host: Pick<import('./createPanelHost.js').PanelHost,
 *   'id' | 'mounted' | 'usesWebGL' | 'loaded' | 'load' | 'mount' | 'unmount'> }} PanelEntry
 */

/**
 * margin: how far off screen a panel counts as near (an IntersectionObserver rootMargin);
 * maxLive: the most WebGL panels mounted at once.
 * @param {PanelEntry[]} entries
 * @param {{ margin?: string, maxLive?: number }} [options]
 */
export function managePanels(entries, { margin = '100% 0px 100% 0px', maxLive = MAX_LIVE_CONTEXTS } = {}) {
  /** @type {Set<PanelEntry>} */
  const near = new Set();
  /** @type {Set<PanelEntry>} */
  const loading = new Set(); // near entries whose module is on its way (they hold a place in the budget)
  /** @type {Set<PanelEntry>} */
  const failed = new Set(); // entries whose module would not load (their notice says so; never retried in a loop)
  // At start only the panels on screen fetch their modules; those just ahead wait until the first
  // picture is up, so the reader's panel is not queued behind modules nobody sees yet.
  let started = false;
  // Until the reader first scrolls, only panels in the window mount: mounting one ahead costs a
  // software GPU ~0.1 s of the page's thread, which is better spent when the reader moves (the
  // places are reserved, so a panel that mounts as it comes into view moves nothing).
  let moved = false;
  /** @param {PanelEntry} entry */
  const inWindow = ({ section }) => {
    const r = section.getBoundingClientRect();
    return r.bottom > 0 && r.top < window.innerHeight;
  };
  /** @param {PanelEntry} entry */
  const onScreen = ({ section }) => {
    const r = section.getBoundingClientRect();
    return r.bottom > 0 && r.top < window.innerHeight / 2; // under the reader's eye, not peeking in at the bottom
  };
  /** @param {PanelEntry} entry */
  const distance = ({ section }) => {
    const r = section.getBoundingClientRect();
    return Math.abs(r.top + r.height / 2 - window.innerHeight / 2);
  };

  // The section under the middle of the screen: mounting panels above it must not move it.
  const anchorEntry = () => {
    const middle = window.innerHeight / 2;
    return entries.find(({ section }) => {
      const r = section.getBoundingClientRect();
      return r.top <= middle && r.bottom >= middle;
    }) ?? null;
  };

  /**
   * Mounts what is near and unmounts what is far; resolves once the modules it asked for have mounted.
   * @returns {Promise<void>}
   */
  function settle() {
    const anchor = anchorEntry();
    const before = anchor ? anchor.section.getBoundingClientRect().top : 0;
    const arrived = mountAndUnmount();
    if (anchor) {
      const shift = anchor.section.getBoundingClientRect().top - before;
      if (Math.abs(shift) >= 1) window.scrollBy(0, shift); // keep the reader's panel where it was
    }
    return arrived;
  }

  /** @returns {Promise<void>} */
  function mountAndUnmount() {
    for (const entry of entries) {
      if (entry.host.mounted && entry.host.usesWebGL && !near.has(entry)) entry.host.unmount();
    }
    const wanted = [...near].sort((a, b) => distance(a) - distance(b));
    let glMounted = entries.filter((e) => (e.host.mounted || loading.has(e)) && e.host.usesWebGL).length;
    /** @type {Promise<void>[]} */
    const arrivals = [];
    for (const entry of wanted) {
      if (entry.host.mounted || loading.has(entry) || failed.has(entry)) continue;
      if (!moved && !inWindow(entry)) continue;
      if (entry.host.usesWebGL) {
        if (glMounted >= maxLive) {
          const farthest = entries.filter((e) => e.host.mounted && e.host.usesWebGL)
            .sort((a, b) => distance(b) - distance(a))[0];
          if (!farthest || distance(farthest) <= distance(entry)) continue;
          farthest.host.unmount();
          glMounted -= 1;
        }
        glMounted += 1;
      }
      if (!entry.host.loaded) {
        if (!started && !onScreen(entry)) {
          glMounted -= entry.host.usesWebGL ? 1 : 0;
          continue;
        }
        loading.add(entry);
        arrivals.push(entry.host.load().catch((error) => {
          failed.add(entry);
          console.warn(`panel ${entry.host.id} failed to load`, error); // its notice is on the page
        }).finally(() => loading.delete(entry)));
        continue;
      }
      try {
        entry.host.mount();
      } catch (error) {
        console.warn(`panel ${entry.host.id} failed to mount`, error); // its notice is on the page
      }
    }
    // Modules that arrive mount in a settle of their own (which keeps the reader's panel in place).
    return arrivals.length ? Promise.all(arrivals).then(() => settle()) : Promise.resolve();
  }

  /** @type {() => void} */
  let firstSettled = () => {};
  /** @type {Promise<void>} */
  const first = new Promise((resolve) => { firstSettled = resolve; });
  const observer = new IntersectionObserver((records) => {
    for (const record of records) {
      const entry = entries.find((e) => e.section === record.target);
      if (!entry) continue;
      if (record.isIntersecting) near.add(entry);
      else near.delete(entry);
    }
    settle().then(() => {
      firstSettled();
      if (started) return;
      // The on-screen panels have mounted and asked for their first frame: after that frame, the rest.
      requestAnimationFrame(() => setTimeout(() => {
        started = true;
        settle();
      }, 0));
    });
  }, { rootMargin: margin });
  for (const { section } of entries) observer.observe(section);

  // When the budget is short, a near panel may wait without any intersection change: scrolling
  // re-ranks by distance (once per frame, and only while some near panel is waiting).
  let pending = 0;
  const onScroll = () => {
    if (!moved) {
      moved = true;
      settle();
    }
    if (pending || ![...near].some((e) => !e.host.mounted && !loading.has(e) && !failed.has(e))) return;
    pending = requestAnimationFrame(() => {
      pending = 0;
      settle();
    });
  };
  window.addEventListener('scroll', onScroll, { passive: true });
  return {
    settle,
    /** Resolves once the panels near the screen at start have mounted. */
    first,
    disconnect() {
      observer.disconnect();
      window.removeEventListener('scroll', onScroll);
    },
  };
}
