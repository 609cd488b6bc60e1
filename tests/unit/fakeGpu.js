// A stand-in for a panel's read-back GPU in Node: a canvas that dispatches the context events, a
// context whose loss a test switches on, and an evaluator whose answers a test writes. Used through
// createReadBackGpu's makeContext and makeEvaluator, so the part itself runs as in the browser.
import { vi } from 'vitest';

export const FULL_PRECISION = Object.freeze({ highpBits: 24, mediumpBits: 24, mediumpIsFullPrecision: true });
export const HALF_PRECISION = Object.freeze({ highpBits: 24, mediumpBits: 11, mediumpIsFullPrecision: false });

/**
 * { canvas, gl, makeContext, makeEvaluator, evaluators, lose(), restore(), loseDuringNextRead() }.
 * evaluate / evaluateSource: (options, evaluator) => Float32Array (defaults: zeros per sample).
 */
export function fakeGpu({ probe = FULL_PRECISION, evaluate, evaluateSource, probeError = null, evaluatorError = null } = {}) {
  const canvas = new EventTarget();
  const state = { lost: false, loseOnRead: false };
  const gl = {
    canvas,
    isContextLost: () => state.lost,
    FRAGMENT_SHADER: 0x8b30,
    HIGH_FLOAT: 0x8df2,
    MEDIUM_FLOAT: 0x8df1,
    getShaderPrecisionFormat: (_stage, type) => ({ rangeMin: 127, rangeMax: 127, precision: type === 0x8df1 ? 10 : 23 }),
  };
  const context = { gl, dispose: vi.fn() };
  const evaluators = [];
  const zeros = (inputs, channels = 1) => new Float32Array((inputs.length / 4) * channels);
  const read = (answer, options, fallback) => {
    if (state.lost) throw new Error('the WebGL context was lost');
    if (state.loseOnRead) {
      state.loseOnRead = false;
      state.lost = true; // lost while the read ran: what it returns is garbage (zeros here)
      return fallback;
    }
    return answer ? answer(options) : fallback;
  };
  const fire = (type) => {
    const event = new Event(type, { cancelable: true });
    canvas.dispatchEvent(event);
    return event;
  };
  return {
    canvas,
    gl,
    context,
    evaluators,
    makeContext: vi.fn(() => context),
    makeEvaluator: vi.fn(() => {
      if (evaluatorError) throw evaluatorError;
      const evaluator = {
        probePrecision: vi.fn(() => {
          if (probeError) throw probeError;
          return probe;
        }),
        evaluate: vi.fn((options) => read(evaluate, options, zeros(options.inputs))),
        evaluateSource: vi.fn((options) => read(evaluateSource, options, zeros(options.inputs, options.channels))),
        forget: vi.fn(),
        dispose: vi.fn(),
      };
      evaluators.push(evaluator);
      return evaluator;
    }),
    /** Loses the context and dispatches the event, as the browser does a moment after a loss. */
    lose() {
      state.lost = true;
      return fire('webglcontextlost');
    },
    /** The context is back: the event, after which everything on it is made anew. */
    restore() {
      state.lost = false;
      return fire('webglcontextrestored');
    },
    /** The next read loses the context (a GPU reset in the middle of it); no event yet. */
    loseDuringNextRead() { state.loseOnRead = true; },
    /** The options of the readBackGpu that use this stand-in. */
    options() { return { makeContext: this.makeContext, makeEvaluator: this.makeEvaluator, canvas: /** @type {any} */ (canvas) }; },
  };
}
