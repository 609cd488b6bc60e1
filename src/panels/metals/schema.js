// @ts-check
// Parameters of the `metals` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { metals } from '../../optics/materials.js';
import { transmittedIndex } from '../shared/indexPair.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  metal: { type: 'enum', default: 'gold', options: metals.map((m) => m.id) },
  fresnel: { type: 'enum', default: 'exact', options: ['exact', 'schlick'] },
  ...transmittedIndex({ aliases: ['n'] }),
};
