// Runs that can go stale. A panel starts a run that outlives the frame it began in (a measurement
// over frames, a GPU read-back, a worker's round trip); a newer run of the same kind, a lost context
// or the panel's dispose makes it stale, and its result must then be dropped, never drawn. One gate
// per kind of run: each run carries an AbortSignal that fetch, workers and loops can take as it is.

/**
 * @typedef {object} Run
 * @property {AbortSignal} signal aborted once the run is stale
 * @property {boolean} live false once a newer run began, the gate was cancelled or disposed
 * @property {() => void} throwIfStale throws the signal's reason when the run is stale
 */

/** A gate whose `begin()` starts a run and makes the one before it stale. */
export function createRunGate() {
  /** @type {AbortController | null} */
  let controller = null;
  let disposed = false;

  const stop = (/** @type {string} */ why) => controller?.abort(new DOMException(why, 'AbortError'));

  return {
    /** Starts a run; the previous one goes stale. After dispose the run is stale from the start. */
    begin() {
      stop('A newer run began');
      const own = new AbortController();
      controller = own;
      if (disposed) own.abort(new DOMException('The panel is gone', 'AbortError'));
      const signal = own.signal;
      /** @type {Run} */
      const run = {
        signal,
        get live() { return !signal.aborted; },
        throwIfStale: () => signal.throwIfAborted(),
      };
      return run;
    },
    /** Makes the current run stale (a lost context, a change that voids it); later runs start live. */
    cancel(why = 'Cancelled') { stop(why); },
    /** Makes the current run stale and every later one stale from its start. */
    dispose() { disposed = true; stop('The panel is gone'); },
  };
}

/** True for the error a stale run throws (its signal's reason), which callers drop without a word. */
export const isStaleRun = (/** @type {unknown} */ error) => error instanceof DOMException && error.name === 'AbortError';
