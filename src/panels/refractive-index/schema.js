// @ts-check
// Parameters of the `refractive-index` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { dielectrics } from '../../optics/materials.js';
import { COLUMN_KEYS } from './columns.js';

export const SELECTABLE = ['none', ...dielectrics.map((m) => m.id), 'custom'];

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  sort: { type: 'enum', default: 'n', options: [...COLUMN_KEYS] },
  dir: { type: 'enum', default: 'asc', options: ['asc', 'desc'] },
  selected: { type: 'enum', default: 'none', options: SELECTABLE },
  customN: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.0001 },
};
