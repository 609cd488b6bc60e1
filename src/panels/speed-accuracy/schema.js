// Parameters of the `speed-accuracy` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { DEFAULT_BUDGET, DISPLAY_BUDGETS } from '../../methods/displayBudgets.js';
import { SCENES } from '../../methods/scenes.js';
import { ERROR_SOURCES } from './errorSources.js';

export const schema = {
  scene: { type: 'enum', default: 'plastic', options: Object.fromEntries(SCENES.map((s) => [s.id, s.label])), label: 'Scene' },
  budget: {
    type: 'enum', default: DEFAULT_BUDGET, options: Object.fromEntries(DISPLAY_BUDGETS.map((b) => [b.id, b.label])), label: 'Error budget',
  },
  errors: { type: 'enum', default: 'js', options: ERROR_SOURCES, label: 'Error measured by' },
  cost: {
    type: 'enum', default: 'gpu',
    options: { gpu: 'GPU ns per evaluation', cpu: 'CPU ns per evaluation (JS)', static: 'Static instruction count' },
    label: 'Cost axis',
  },
};
