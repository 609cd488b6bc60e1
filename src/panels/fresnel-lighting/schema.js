// Parameters of the `fresnel-lighting` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { transmittedIndex } from '../shared/indexPair.js';

export const schema = {
  ...transmittedIndex({ what: 'coat', aliases: ['n'] }),
  method: {
    type: 'enum', default: 'exact',
    options: { exact: 'Exact Fresnel', schlick: "Schlick's approximation", layered: 'Layered coat, exact F (beyond the lecture)' },
    label: 'F on the Fresnel sphere',
  },
  weight: { type: 'number', default: 0.04, min: 0, max: 1, step: 0.001, label: 'Constant ks weight w (other sphere)' },
  kd: { type: 'color', default: '#a3241c', label: 'kd (diffuse layer)' },
  ks: { type: 'color', default: '#ffffff', label: 'ks (coat)' },
  lightAz: { type: 'number', default: 35, min: -180, max: 180, step: 1, label: 'Light azimuth °' },
  lightEl: { type: 'number', default: 40, min: -10, max: 90, step: 1, label: 'Light elevation °' },
};
