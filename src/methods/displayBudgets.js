// How much display error a scene may show: budgets in 8-bit sRGB codes for advisor.recommend,
// and the scene-weighted average display error to show beside the worst one.
//
// The criterion is advisor.js's: the worst sample over the scene's domain, at the brightest
// light (display white), after the sRGB transform, in 8-bit codes. Under the strictest line, half a
// step (no more than the display's own rounding), no Schlick variant passes for opaque plastic: its
// worst pixel is 12.1 codes off (n = 1.3 at 80.6°; |ΔR| itself peaks at 83.6°, 11.1 codes there),
// and even its average pixel, weighted by projected area (the scene's cosine weighting), is 4.0
// codes off, because sRGB steepens the small errors of dark reflections. Schlick is nonetheless the
// usual choice there, as Filament (F_Schlick), Godot (SchlickFresnel), three.js (F_Schlick) and UE4
// (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013) ship it: that is a judgement that a
// visible rim error of a few percent is acceptable. The "acceptable" budget states that judgement
// as a number, 5 % of the display range (12.75 codes), and says it is one; the student picks the budget.
import { displayCodes, recommend } from './advisor.js';
import { sweepDomain } from './errorMetrics.js';
import { contextFor } from './rounding.js';
import { referenceFor } from './scenes.js';
import { DEFAULT_BUDGET } from './ids.js';
import english from 'virtual:messages/en/methods';
import { messages } from '../i18n/messages.js';

const t = messages('methods', english);

/** The budgets; each one's label is the catalogue's (budget.<id>), in the page's language. */
export const DISPLAY_BUDGETS = Object.freeze([
  { id: 'invisible', codes: 0.5 }, // the id stays: links use it (the label says "within rounding")
  { id: 'one-code', codes: 1 },
  { id: 'one-percent', codes: 2.55 },
  { id: 'acceptable', codes: 12.75 },
  { id: 'ten-percent', codes: 25.5 },
].map(({ id, codes }) => Object.freeze({ id, codes, get label() { return t(`budget.${id}`); } })));

export { DEFAULT_BUDGET };

/** The budget with this id; throws on an unknown id. */
export function displayBudget(id) {
  const found = DISPLAY_BUDGETS.find((b) => b.id === id);
  if (!found) throw new RangeError(`unknown display budget ${String(id)}`);
  return found;
}

/** The criterion in words, for the panel and the recommendation. */
export const criterionText = () => t('criterion');

const meanCache = new WeakMap();

/**
 * Average display error in 8-bit codes over the scene's domain with the scene's weighting
 * (cosine: share of an object's pixels; uniform θ: every angle alike). NaN samples are left
 * out of the mean (advisor's max already makes such a method fail). Cached per scene object.
 */
export function meanDisplayCodes(scene, method, precision = scene.precision) {
  const P = contextFor(precision);
  if (!meanCache.has(scene)) meanCache.set(scene, new Map());
  const cache = meanCache.get(scene);
  const key = `${method.id}|${P.name}`;
  if (!cache.has(key)) {
    cache.set(key, sweepDomain({
      evaluate: (cos, ...args) => method.evaluate(P, cos, ...args),
      reference: referenceFor(scene.kind),
      cases: scene.cases,
      thetaCount: scene.thetaCount,
      weighting: scene.weighting,
      metric: displayCodes,
    }).mean);
  }
  return cache.get(key);
}

/**
 * advisor.recommend under a named budget: { ...recommend(), budget, criterion }. costs as for
 * recommend ({ methodId: cost }, one unit, every method or none).
 */
export function recommendWithin(scene, costs, budgetId = DEFAULT_BUDGET, options = {}) {
  const budget = displayBudget(budgetId);
  return { ...recommend(scene, costs, { ...options, budgetCodes: budget.codes }), budget, criterion: criterionText() };
}
