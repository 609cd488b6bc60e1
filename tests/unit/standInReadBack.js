// A stand-in for the GPU's read-back in the speed-accuracy tests: every method of the scene's kind
// off the float64 reference by a constant of its own (1e-4 × (index + 1)), through the same
// statistics as a real read-back (errorsFromValues).
import { errorsFromValues } from '../../src/methods/gpuErrors.js';
import { thetaSamples } from '../../src/methods/errorMetrics.js';
import { methodsOfKind } from '../../src/methods/methods.js';
import { referenceFor } from '../../src/methods/scenes.js';

/** Each method's errors, keyed by id, as the read-back reports them. */
export function offsetErrors(scene) {
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  const reference = referenceFor(scene.kind);
  return Object.fromEntries(methodsOfKind(scene.kind).map((method, i) => {
    const values = new Float64Array(scene.cases.flatMap((args) => Array.from(cos, (c) => reference(c, ...args) + 1e-4 * (i + 1))));
    return [method.id, errorsFromValues(scene, values)];
  }));
}
