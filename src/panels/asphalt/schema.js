// @ts-check
// Parameters of the `asphalt` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { transmittedIndex } from '../shared/indexPair.js';

// No published refractive index of bitumen was found; 1.55 is an assumption in the range of
// organic binders and plastics (1.5–1.6).
/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  camEl: { type: 'number', default: 6, min: 2, max: 90, step: 0.5 },
  sunEl: { type: 'number', default: 10, min: 2, max: 45, step: 0.5 },
  roughness: { type: 'number', default: 0.8, min: 0.2, max: 1, step: 0.01 },
  ...transmittedIndex({ nT: 1.55, aliases: ['n'] }),
  fresnel: { type: 'boolean', default: true },
};
