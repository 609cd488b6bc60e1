// @ts-check
// The state and the runs of the normal-mips panel, apart from its DOM: the chains of the current
// settings (built off the page's thread), the changes that wait for them, what the GPU scene is
// told, and the shimmer measurement. index.js is the view: it draws what the runs hold when a
// hook says so, in words.js's words (these runs keep states and causes as data). Long runs (a
// chain build, a shimmer measurement) go stale through run gates: a newer run, a change of the
// settings they measure, a lost context or dispose drops their result.
import { levelCount } from '../../normals/momentPyramid.js';
import { createRunGate, isStaleRun } from '../shared/createRunGate.js';
import {
  CHAIN_KEYS, chainRequest, ERROR_KEYS, mergeKeys, sceneSettings, SHIMMER_KEYS, touches, TRUTH_KEYS,
} from './sceneSettings.js';

/**
 * The line over the stage: the chains of a map of `size`² are building, or their build failed
 * (`error`); null hides it. words.js's busyText says it.
 * @typedef {{ size: number } | { error: Error } | null} ChainBuildState
 */

/**
 * Why the last shimmer measurement ended without numbers: '' it did not, 'lost' the graphics
 * context went under it. words.js's shimmerStoppedText says it.
 * @typedef {'' | 'lost'} ShimmerStop
 */

/**
 * What the runs need of the GPU scene (createNormalMipsScene), so a stand-in can take its place.
 * @typedef {object} NormalMipsScene
 * @property {number} maxAnisotropy
 * @property {boolean} floatLinear
 * @property {{ samples: number, cap: number, errors: any }} state
 * @property {(chains: any, uploads?: any) => void} setChains
 * @property {(settings: Record<string, any>, truthChanged: boolean) => void} set
 * @property {() => void} refreshErrors
 * @property {(options?: { signal?: AbortSignal }) => Promise<Record<string, number> | null>} measureShimmer
 */

/**
 * What the view does when the state changes.
 * @typedef {object} NormalMipsHooks
 * @property {(keys: string[] | null | undefined) => void} applied  settings were applied (keys: which, [] a re-describe, null all)
 * @property {(state: ChainBuildState) => void} busy  the chains started building, failed, or are there (null)
 * @property {() => void} summary  the line of key numbers must be written again (before the first chains arrive)
 * @property {() => void} shimmer  the shimmer meter's state changed
 * @property {() => void} invalidate  a result arrived: describe the panel again
 */

/**
 * @param {{ values: import('../../host/panelContract.js').ValuesOf<typeof import('./schema.js').schema>,
 *   builder: { build: (request: any) => Promise<any>, workers: number, problem: any, dispose: () => void },
 *   scene: NormalMipsScene | null, hooks: NormalMipsHooks }} options
 *   values: the host's live values; builder: createChainBuilder(); scene: null without WebGL2
 */
export function createNormalMipsRuns({ values, builder, scene, hooks }) {
  const buildGate = createRunGate();
  const shimmerGate = createRunGate();
  let chains = null;
  let pyramid = null;
  let built = { ms: 0, workers: builder.workers, size: 0 };
  /** @type {string[] | null | undefined} keys waiting for a chain build (null: all); undefined when none is running */
  let deferred;
  /** @type {Promise<void>} */
  let buildDone = Promise.resolve();
  /** result: the last numbers (null: none for these settings); stopped: why the last run ended without numbers */
  const shimmer = { result: /** @type {Record<string, number> | null} */ (null), busy: false, stopped: /** @type {ShimmerStop} */ ('') };

  /** The anisotropic taps in use: what was asked for, as far as this GPU offers them. */
  const anisotropyInUse = () => (scene ? Math.min(Number(values.anisotropy), scene.maxAnisotropy) : 1);

  // Chains are built off the page's thread (createChainBuilder); until the newest build arrives
  // the old picture stays and every other change waits, so picture, strip and truth always
  // belong to the same map.
  function rebuildChains(/** @type {string[] | null | undefined} */ keys) {
    deferred = mergeKeys(deferred, keys);
    hooks.busy({ size: Number(values.size) });
    if (!chains) hooks.summary(); // the panel has its full height from its mount on
    const run = buildGate.begin();
    const request = chainRequest(values);
    buildDone = builder.build(request).then((result) => {
      if (!result || !run.live) return; // a newer build was asked for, or the panel is gone
      ({ chains, pyramid } = result);
      built = { ms: result.ms, workers: result.workers, size: request.size };
      scene?.setChains(chains, result.uploads);
      const keysNow = deferred;
      deferred = undefined;
      hooks.busy(null);
      apply(keysNow);
      hooks.invalidate(); // re-describe, now with this map
    }, (error) => {
      if (!run.live) return;
      deferred = undefined;
      hooks.busy({ error });
    });
  }

  function resetShimmer() {
    shimmerGate.cancel('The settings changed');
    shimmer.result = null;
    shimmer.busy = false;
    shimmer.stopped = '';
  }

  /** Tells the scene the settings, then the view. */
  function apply(/** @type {string[] | null | undefined} */ keys) {
    const has = touches(keys);
    if (has(SHIMMER_KEYS)) resetShimmer();
    if (scene && keys?.length !== 0) { // [] is a re-describe (new errors, a finished build): nothing to draw
      const levels = levelCount(Number(values.size));
      scene.set(sceneSettings(values, { levels, anisotropy: anisotropyInUse() }), has(TRUTH_KEYS));
      // The truth does not depend on what the techniques store, the forced level or the filtering: only the errors do.
      if (!has(TRUTH_KEYS) && has(ERROR_KEYS)) scene.refreshErrors();
    }
    hooks.applied(keys);
  }

  /** Resolves once the newest chain build has been applied. */
  async function whenBuilt() {
    for (let b; b !== buildDone;) {
      b = buildDone;
      await b;
    }
  }

  return {
    get chains() { return chains; },
    get pyramid() { return pyramid; },
    /** { ms, workers, size } of the chains shown (size 0 before the first build; workers 0: the page's thread). */
    get built() { return built; },
    /** Why the chains are built on the page's thread although workers were asked for (the builder's; null when they are not). */
    get problem() { return builder.problem; },
    /** True while a chain build runs and changes wait for it. */
    get building() { return deferred !== undefined; },
    /** { result, busy, stopped } of the shimmer meter. */
    get shimmer() { return shimmer; },
    anisotropyInUse,
    whenBuilt,
    /**
     * Values changed (keys: which; [] a re-describe; none: everything, as at mount).
     * @param {string[] | null} [keys]
     */
    update(keys) {
      const has = touches(keys);
      if (!chains || !keys || has(CHAIN_KEYS)) rebuildChains(keys);
      else if (deferred !== undefined) deferred = mergeKeys(deferred, keys);
      else apply(keys);
    },
    /**
     * Measures every technique's shimmer on the chains of the current settings; a newer
     * measurement, a change of what it measures, a lost context or dispose drops its result.
     */
    async measureShimmer() {
      await whenBuilt();
      const run = shimmerGate.begin();
      if (!run.live) return; // the panel is gone
      shimmer.busy = true;
      shimmer.stopped = '';
      hooks.shimmer();
      let result;
      try {
        result = await scene?.measureShimmer({ signal: run.signal }) ?? null;
      } catch (error) {
        if (isStaleRun(error)) return;
        throw error;
      }
      if (!run.live) return;
      shimmer.busy = false;
      shimmer.result = result;
      // null from a live scene: its context was lost under the read-backs
      if (result === null && scene) shimmer.stopped = 'lost';
      hooks.shimmer();
      hooks.invalidate();
    },
    /** The scene's context was lost: a running shimmer measurement stops and says why. */
    contextLost() {
      if (!shimmer.busy) return;
      shimmerGate.cancel('The graphics context was lost');
      shimmer.busy = false;
      shimmer.result = null;
      shimmer.stopped = 'lost';
      hooks.shimmer();
      hooks.invalidate();
    },
    dispose() {
      buildGate.dispose();
      shimmerGate.dispose();
      builder.dispose();
    },
  };
}
