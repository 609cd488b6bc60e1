// Work that goes on for a while (a benchmark, a series of read-backs) runs only while its panel is
// on screen: between its steps it awaits whenVisible(), which resolves at once while the element
// intersects the window and otherwise when it comes back.

/**
 * @param {Element} element
 * @param {{ onPause?: () => void, onResume?: () => void }} [hooks] said when a step has to wait, and when it may go on
 */
export function createVisibilityGate(element, { onPause, onResume } = {}) {
  let visible = true; // until the observer's first report: a panel is mounted because it is near
  let waiting = [];
  const observer = new IntersectionObserver(([record]) => {
    visible = record.isIntersecting;
    if (!visible || !waiting.length) return;
    const resume = waiting;
    waiting = [];
    onResume?.();
    resume.forEach((resolve) => resolve());
  });
  observer.observe(element);
  return {
    get visible() { return visible; },
    whenVisible() {
      if (visible) return Promise.resolve();
      if (!waiting.length) onPause?.();
      return new Promise((resolve) => { waiting.push(resolve); });
    },
    dispose() {
      observer.disconnect();
      const resume = waiting;
      waiting = [];
      resume.forEach((resolve) => resolve()); // a disposed panel's run ends through its signal
    },
  };
}
