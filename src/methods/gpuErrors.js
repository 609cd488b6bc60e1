// Errors of values computed elsewhere (read back from the GPU, evaluateMethodsGpu) over a scene's
// domain: the same samples, weights and statistics as advisor.methodError (errorMetrics.sweepDomain
// with displayCodes alongside), so a figure measured on the GPU and one from the JS emulation
// differ only where the arithmetic differs. The advisor's choice can then be made from them.
import { HALF_STEP_CODES, recommend, sceneErrors } from './advisor.js';
import { thetaSamples } from './errorMetrics.js';
import { f82Coefficients } from './methods.js';

/** Samples in a scene's domain: every case at every angle. */
export function domainSize(scene) {
  return scene.cases.length * scene.thetaCount;
}

/**
 * GPU inputs for a scene's domain, 4 floats per sample in sweepDomain's order (sample
 * k = case·thetaCount + i): (cos θ, nI, nT, 0) for dielectrics, (cos θ, n, k, f0) for conductors
 * (the layout evaluateMethodsGpu reads). Float32Array rounds each input as a uniform would.
 */
export function domainInputs(scene) {
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  const inputs = new Float32Array(domainSize(scene) * 4);
  scene.cases.forEach((args, c) => {
    const rest = scene.kind === 'dielectric' ? [args[0], args[1], 0] : [args[0], args[1], args[2]];
    for (let i = 0; i < cos.length; i += 1) inputs.set([cos[i], ...rest], (c * cos.length + i) * 4);
  });
  return inputs;
}

/**
 * The per-sample extra input of a method, or null: F82's b, computed in float64 from the case's
 * own n, k, F0 as the JS twin does (methods.js f82B), rather than from the float32 inputs.
 */
export function domainExtra(scene, methodId) {
  if (methodId !== 'conductor-f82') return null;
  const extra = new Float32Array(domainSize(scene) * 4);
  scene.cases.forEach(([n, k, f0], c) => {
    const { b } = f82Coefficients(n, k, f0);
    for (let i = 0; i < scene.thetaCount; i += 1) extra[(c * scene.thetaCount + i) * 4] = b;
  });
  return extra;
}

/**
 * Error statistics of values (one per sample, domainInputs' order) against the scene's float64
 * reference: methodError's shape { count, max, mean, rms, thetaAtMax, nanCount, outOfRange,
 * caseAtMax, maxCodes, meanCodes } (advisor.sceneErrors). NaN and
 * Infinity count as sweepDomain counts them (nanCount, max = Infinity, left out of the means).
 */
export function errorsFromValues(scene, values) {
  const size = domainSize(scene);
  if (!values || values.length !== size) throw new RangeError(`expected ${size} values, got ${values?.length}`);
  const { cos } = thetaSamples(scene.thetaCount, scene.weighting);
  let k = 0;
  // sweepDomain evaluates case by case, angle by angle, once each: sample k. The check keeps
  // this true if its order ever changes.
  return sceneErrors(scene, (c) => {
    if (c !== cos[k % cos.length]) throw new Error('sweepDomain visited the samples in an unexpected order');
    const value = values[k];
    k += 1;
    return value;
  });
}

/**
 * advisor.recommend with errors measured elsewhere (errorsFromValues of a read-back): { methodId:
 * stats } for every method of the scene's kind; where names them in the reason (default: the
 * scene's label); precision is returned as given.
 * @param {object} scene
 * @param {Record<string, object>} errors
 * @param {Record<string, number>} [costs]
 * @param {{ budgetCodes?: number, where?: string, precision?: string }} [options]
 */
export function recommendWithErrors(scene, errors, costs = {}, { budgetCodes = HALF_STEP_CODES, where, precision } = {}) {
  return recommend(scene, costs, { budgetCodes, precision, errors, where: where ?? scene.label });
}
