// @ts-check
// Parameters of the `refraction-waves` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { indexPair } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  angle: { type: 'number', default: 30, min: 0, max: 89, step: 0.1 },
  ...indexPair({ step: 0.001, aliases: { nI: ['n1'], nT: ['n2'] } }),
  reflected: { type: 'boolean', default: false },
  play: { type: 'boolean', default: true },
  speed: { type: 'number', default: 0.5, min: 0.05, max: 2, step: 0.05 },
};
