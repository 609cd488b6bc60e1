// @ts-check
// Parameters of the `schlick` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { indexPair } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  ...indexPair(),
  theta: { type: 'number', default: 60, min: 0, max: 90, step: 0.01 },
};
