// The normal-mips part of `npm run bench`: how long building every technique's chain takes for a
// map of a given size in this browser (issue: "well under a second for 1024²"), and whether the
// page stays responsive meanwhile. Wall time runs from the request to the arrival of the
// transferred arrays, so it includes the worker's start-up share and the transfer; the longest
// main-thread task (Long Tasks API: tasks over 50 ms) over the same stretch shows what input
// would have waited for. The first build warms the worker and is not counted.
import { createChainBuilder } from '../../normals/createChainBuilder.js';
import { spreadOf } from '../../methods/timeMethodsCpu.js';

/** Runs fn while recording long tasks; resolves to { value, longestTaskMs } (0: none over 50 ms). */
export async function watchLongTasks(fn) {
  const durations = [];
  let observer = null;
  if (typeof PerformanceObserver !== 'undefined' && PerformanceObserver.supportedEntryTypes?.includes('longtask')) {
    observer = new PerformanceObserver((list) => { for (const e of list.getEntries()) durations.push(e.duration); });
    observer.observe({ type: 'longtask' });
  }
  try {
    const value = await fn();
    await new Promise((resolve) => { setTimeout(resolve, 100); }); // long-task entries arrive late
    for (const e of observer?.takeRecords() ?? []) durations.push(e.duration);
    return { value, longestTaskMs: durations.length ? Math.max(...durations) : 0, observed: Boolean(observer) };
  } finally {
    observer?.disconnect();
  }
}

/**
 * benchChainBuild({ size = 1024, repeats = 5, request }) → { size, where, wallMs, buildMs,
 * longestTaskMs, longTasksObserved }: wallMs and buildMs (inside the worker) as { median, min, max }.
 */
export async function benchChainBuild({ size = 1024, repeats = 5, request = {} } = {}) {
  const builder = createChainBuilder();
  const full = { kind: 'bumps', params: { frequency: 16, edgeAngleDeg: 35 }, size, precision: 'f16', channels: 3, ...request };
  try {
    await builder.build(full); // warm-up
    const wall = [];
    const inside = [];
    const { longestTaskMs, observed } = await watchLongTasks(async () => {
      for (let r = 0; r < repeats; r += 1) {
        const t0 = performance.now();
        const result = await builder.build(full);
        wall.push(performance.now() - t0);
        inside.push(result.ms);
      }
    });
    return {
      size, where: builder.where, wallMs: spreadOf(wall), buildMs: spreadOf(inside), longestTaskMs, longTasksObserved: observed,
    };
  } finally {
    builder.dispose();
  }
}
