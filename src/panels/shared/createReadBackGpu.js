// @ts-check
// A panel's read-back GPU: a WebGL2 context of its own (never on the page, counted in the page's
// budget), the method evaluator on it (evaluateMethodsGpu.js: render into RGBA32F, read back), what
// mediump really is there, and a sentence for each GPU problem a user can meet: no WebGL2, no float
// render targets, a shader of the panel's own refused by the driver, a lost context. It asks for the
// restore after a loss and makes the evaluator anew then, as startWebGL and createShaderView do for
// pictures. Runs on it come from its gates (createRunGate.js): a loss makes the running one stale,
// dispose every one. Plain JS apart from the context it is given, so runs are tested in Node with a
// stand-in context and evaluator.
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { createContext } from '../../gl/createContext.js';
import { createMethodsGpu, GpuFloatUnavailable, gpuPrecisionInfo } from '../../gl/evaluateMethodsGpu.js';
import { refusalLine, ShaderError } from '../../gl/shaderError.js';
import { createRunGate } from './createRunGate.js';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

/** @typedef {ReturnType<typeof createMethodsGpu>} MethodsGpu */
/** @typedef {import('./createRunGate.js').Run} Run */
/** @typedef {ReturnType<typeof createRunGate>} RunGate */

/**
 * What the panel says, in its own words.
 * @typedef {object} ReadBackWords
 * @property {string} unavailable  after the browser's own sentence when there is no WebGL2 or no
 *   float render target: what needs them, and what still works
 * @property {(line: string) => string} refused  the sentence when the driver refuses a shader of the
 *   panel's own, given the driver's first error line (or the error's first line)
 * @property {string} lost  the sentence while the context is gone
 * @property {(error: Error) => string} [restartFailed]  the sentence when the evaluator does not start
 *   again after a restore (by default as at the start, or "The GPU evaluator could not start again: …")
 */

/**
 * What mediump and highp are here: probe (probePrecision: measured by rendering) and claimed
 * (gpuPrecisionInfo: what the driver says, not trusted).
 * @typedef {{ probe: { highpBits: number, mediumpBits: number, mediumpIsFullPrecision: boolean }, claimed: any }} PrecisionFacts
 */

/**
 * @template [P=null]
 * @typedef {object} ReadBackOptions
 * @property {ReadBackWords} words
 * @property {(evaluator: MethodsGpu, gl: WebGL2RenderingContext) => P} [prepare]  more of the panel's
 *   own on the context (a painter, say), made after the evaluator at the start and after each restore;
 *   its errors are worded as the evaluator's. Its result is `prepared`; a dispose() of it is called at the end
 * @property {() => void} [onChange]  after the context is lost and after it is restored (a panel: ctx.invalidate)
 * @property {HTMLCanvasElement} [canvas]  the context's canvas (default: a new one, never on the page)
 * @property {(canvas: HTMLCanvasElement) => { gl: WebGL2RenderingContext, dispose: () => void }} [makeContext]
 *   createContext by default (tests: a stand-in)
 * @property {(gl: WebGL2RenderingContext) => MethodsGpu} [makeEvaluator]  createMethodsGpu by default
 */

/** A GPU problem in the panel's words, or '' for an error that is no GPU problem (the panel's own bug). */
function wordProblem(error, words) {
  if (error instanceof ShaderError) {
    console.error(error); // the whole log, for whoever reports it
    return words.refused(refusalLine(error) || error.message.split('\n')[0]);
  }
  if (error instanceof WebGL2Unavailable || error instanceof GpuFloatUnavailable) return `${error.message} ${words.unavailable}`;
  return '';
}

/**
 * Starts the read-back GPU of a panel. Never throws for a GPU problem: `problem` says it and
 * `evaluator` is null; an error that is no GPU problem (a bug) propagates.
 * @template [P=null]
 * @param {ReadBackOptions<P>} options
 */
export function createReadBackGpu({
  words, prepare = () => /** @type {P} */ (null), onChange = () => {}, canvas,
  makeContext = createContext, makeEvaluator = createMethodsGpu,
}) {
  /** @type {{ gl: WebGL2RenderingContext, dispose: () => void } | null} */
  let context = null;
  /** @type {MethodsGpu | null} */
  let evaluator = null;
  /** @type {P | null} */
  let prepared = null;
  /** @type {PrecisionFacts | null} */
  let precision = null;
  let problem = ''; // why there is no evaluator ('' while there is one)
  let lost = false;
  let disposed = false;
  /** @type {Set<RunGate>} */
  const gates = new Set();

  /** The evaluator, what mediump is, and the panel's part; a GPU problem is kept in words. */
  function start(again) {
    if (!context) return; // `problem` says why
    evaluator = null;
    prepared = null;
    problem = '';
    const { gl } = context;
    /** @type {MethodsGpu | null} */
    let made = null;
    try {
      made = makeEvaluator(gl);
      precision = { probe: made.probePrecision(), claimed: gpuPrecisionInfo(gl) };
      prepared = prepare(made, gl);
      evaluator = made;
    } catch (error) {
      prepared = null;
      made?.dispose(); // what it made on the context so far
      if (!again) {
        problem = wordProblem(error, words);
        if (!problem) throw error;
        return;
      }
      // After a restore nothing may throw out of the event; every failure is said.
      problem = words.restartFailed?.(error) || wordProblem(error, words) || t('evaluatorRestartFailed', { error: error.message });
    }
  }

  /** A loss, from the event or found by a run: every run on the context goes stale. */
  function markLost() {
    lost = true;
    for (const gate of gates) gate.cancel(words.lost);
  }

  // The event comes after whatever run found the loss; a restore makes everything on the context anew.
  const onLost = (/** @type {Event} */ event) => {
    event.preventDefault(); // asks for the restore
    markLost();
    onChange();
  };
  const onRestored = () => {
    lost = false;
    start(true);
    onChange();
  };

  try {
    context = makeContext(canvas ?? document.createElement('canvas'));
  } catch (error) {
    problem = wordProblem(error, words);
    if (!problem) throw error;
  }
  const target = /** @type {HTMLCanvasElement | null} */ (context?.gl.canvas ?? null);
  target?.addEventListener('webglcontextlost', onLost);
  target?.addEventListener('webglcontextrestored', onRestored);
  start(false);

  const isLost = () => lost || Boolean(context?.gl.isContextLost());

  return {
    /** The context (for tests that lose and restore it), or null without WebGL2. */
    get gl() { return context?.gl ?? null; },
    /** The method evaluator, or null when it could not start (see `problem`). */
    get evaluator() { return evaluator; },
    /** What prepare() made, or null. */
    get prepared() { return prepared; },
    /** What mediump and highp are on this GPU, measured when the evaluator started; null before it ever did. */
    get precision() { return precision; },
    /** True from a loss (its event, or a run that found it) until the restore. */
    get lost() { return isLost(); },
    /** True when a run can read back now: an evaluator on a live context. */
    get ready() { return Boolean(evaluator) && !isLost() && !disposed; },
    /** Why nothing can be read back now, in the panel's words: the loss, or what stopped the start; '' when ready. */
    get problem() { return isLost() ? words.lost : problem; },
    /** A gate for one kind of run on this GPU: a loss makes its current run stale, dispose every run. */
    gate() {
      const gate = createRunGate();
      gates.add(gate);
      if (disposed) gate.dispose();
      return gate;
    },
    /**
     * fn(evaluator) as a step of `run` (from one of this part's gates), which must be live and the
     * GPU ready. A loss found during the step (the event comes later) is taken as the event will
     * be, and the run's stale error is thrown instead of the step's result or error; any other
     * error propagates as thrown.
     * @template T
     * @param {Run} run
     * @param {(evaluator: MethodsGpu) => T} fn
     * @returns {T}
     */
    read(run, fn) {
      run.throwIfStale();
      if (!evaluator || isLost()) throw new Error(`Nothing can be read back now: ${this.problem}`);
      let result;
      try {
        result = fn(evaluator);
      } catch (error) {
        if (context?.gl.isContextLost()) markLost();
        run.throwIfStale();
        throw error;
      }
      if (context?.gl.isContextLost()) markLost();
      run.throwIfStale(); // a newer run may have begun inside fn, too
      return result;
    },
    /** Frees the runs, the panel's part, the evaluator and the context (and its place in the budget). */
    dispose() {
      if (disposed) return;
      disposed = true;
      for (const gate of gates) gate.dispose();
      target?.removeEventListener('webglcontextlost', onLost);
      target?.removeEventListener('webglcontextrestored', onRestored);
      /** @type {any} */ (prepared)?.dispose?.();
      evaluator?.dispose();
      context?.dispose();
    },
  };
}

/** @typedef {ReturnType<typeof createReadBackGpu>} ReadBackGpu */
