// Parameters of the `stability` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { invisibleThreshold } from '../../methods/advisor.js';
import { methodsOfKind } from '../../methods/methods.js';

export const DIELECTRICS = methodsOfKind('dielectric');

export const schema = {
  method: { type: 'enum', default: 'exact-cg', options: Object.fromEntries(DIELECTRICS.map((m) => [m.id, m.label])), label: 'Method' },
  precision: {
    type: 'enum', default: 'mediump', label: 'Precision',
    options: { fp64: 'JS float64', fp32: 'JS float32', fp16: 'JS float16', highp: 'GPU highp', mediump: 'GPU mediump' },
  },
  tolerance: { type: 'number', default: invisibleThreshold(), min: 0, max: 0.5, step: 1e-7, label: 'Tolerance |R − R_exact|' },
};
