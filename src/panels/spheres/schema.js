// @ts-check
// Parameters of the `spheres` panel: controls, URL keys (?nI=1&nT=1.5&...) and messages all use them.
// Pure data, so Node tests can check URL parsing without a browser.
import { indexPair } from '../shared/indexPair.js';

const ERROR_SCALES = ['auto', '0.005', '0.01', '0.02', '0.05', '0.1', '0.2', '0.5', '1'];

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  ...indexPair(),
  kd: { type: 'color', default: '#a3241c' },
  ks: { type: 'color', default: '#ffffff' },
  lightAz: { type: 'number', default: 35, min: -180, max: 180, step: 1 },
  lightEl: { type: 'number', default: 40, min: -10, max: 90, step: 1 },
  env: { type: 'number', default: 1, min: 0, max: 2, step: 0.01 },
  errScale: { type: 'enum', default: 'auto', options: ERROR_SCALES },
  viewAz: { type: 'number', default: 0, min: -180, max: 180, step: 0.1 },
  viewEl: { type: 'number', default: 12, min: -85, max: 85, step: 0.1 },
  viewDist: { type: 'number', default: 6, min: 2.2, max: 10, step: 0.01 },
};

