// Render on demand: any number of requests within one animation frame draw once, and nothing
// draws while nothing changes. `frames` counts the draws so tests can check that.
export function onDemand(draw) {
  let pending = 0;
  const state = {
    frames: 0,
    request() {
      if (pending) return;
      pending = requestAnimationFrame(() => {
        pending = 0;
        state.frames += 1;
        draw();
      });
    },
    cancel() {
      if (pending) cancelAnimationFrame(pending);
      pending = 0;
    },
  };
  return state;
}
