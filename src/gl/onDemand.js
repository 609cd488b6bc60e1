// Render on demand: any number of requests within one animation frame draw once, and nothing
// draws while nothing changes. `frames` counts the draws so tests can check that. A draw that
// throws is the fault of the panel that made the loop (panelFaults.js), said in that panel.
import { currentOwner } from './faultOwner.js';

export function onDemand(draw) {
  const owner = currentOwner();
  let pending = 0;
  const state = {
    frames: 0,
    request() {
      if (pending) return;
      pending = requestAnimationFrame(() => {
        pending = 0;
        state.frames += 1;
        if (!owner) {
          draw();
          return;
        }
        try {
          draw();
        } catch (error) {
          owner.fail(error);
        }
      });
    },
    cancel() {
      if (pending) cancelAnimationFrame(pending);
      pending = 0;
    },
  };
  return state;
}
