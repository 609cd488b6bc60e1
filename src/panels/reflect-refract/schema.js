// @ts-check
// Parameters of the `reflect-refract` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { transmittedIndex } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  elevation: { type: 'number', default: 30, min: 2, max: 90, step: 0.1 },
  ...transmittedIndex({ nT: 1.333, step: 0.0001, aliases: ['n'] }),
  depth: { type: 'number', default: 1.5, min: 0.2, max: 5, step: 0.1 },
  layer: {
    type: 'enum', default: 'both',
    options: ['both', 'reflected', 'refracted'],
  },
};
