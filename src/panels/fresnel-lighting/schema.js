// @ts-check
// Parameters of the `fresnel-lighting` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { transmittedIndex } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  ...transmittedIndex({ aliases: ['n'] }),
  method: {
    type: 'enum', default: 'exact',
    options: ['exact', 'schlick', 'layered'],
  },
  weight: { type: 'number', default: 0.04, min: 0, max: 1, step: 0.001 },
  kd: { type: 'color', default: '#a3241c' },
  ks: { type: 'color', default: '#ffffff' },
  lightAz: { type: 'number', default: 35, min: -180, max: 180, step: 1 },
  lightEl: { type: 'number', default: 40, min: -10, max: 90, step: 1 },
};
