// @ts-check
// Parameters of the `changing-specular` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { transmittedIndex } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  lightEl: { type: 'number', default: 30, min: 1, max: 90, step: 0.5 },
  viewEl: { type: 'number', default: 30, min: 1, max: 90, step: 0.5 },
  linked: { type: 'boolean', default: true },
  s: { type: 'number', default: 60, min: 1, max: 500, step: 1 },
  ...transmittedIndex({ aliases: ['n'] }),
};
