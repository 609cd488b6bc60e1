// @ts-check
// Parameters of the `speed-accuracy` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { BUDGET_IDS, DEFAULT_BUDGET, SCENE_IDS } from '../../methods/ids.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  scene: { type: 'enum', default: 'plastic', options: [...SCENE_IDS] },
  budget: {
    type: 'enum', default: DEFAULT_BUDGET, options: [...BUDGET_IDS],
  },
  errors: { type: 'enum', default: 'js', options: ['js', 'gpu-highp', 'gpu-mediump'] },
  cost: {
    type: 'enum', default: 'gpu',
    options: ['gpu', 'cpu', 'static'],
  },
};
