// @ts-check
// Parameters of the `stability` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { invisibleThreshold } from '../../methods/displayThreshold.js';
import { DIELECTRIC_METHOD_IDS } from '../../methods/ids.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  method: { type: 'enum', default: 'exact-cg', options: [...DIELECTRIC_METHOD_IDS] },
  precision: {
    type: 'enum', default: 'mediump',
    options: ['fp64', 'fp32', 'fp16', 'highp', 'mediump'],
  },
  tolerance: { type: 'number', default: invisibleThreshold(), min: 0, max: 0.5, step: 1e-7 },
};
