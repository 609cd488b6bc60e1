// @ts-check
// The indices of refraction of an interface as the lecture writes them: n_i on the side the light
// comes from, n_t on the side it goes to. One schema part for every panel with two media, one for
// the panels whose light always comes from air (n_i = 1), and the swap button.

const INDEX_RANGE = { min: 1, max: 3 };

/** @typedef {import('../../host/panelContract.js').NumberSpec} NumberSpec */

/**
 * { nI, nT } schema entries. aliases: older URL keys of each ({ nI: ['n1'], nT: ['n2'] }), so
 * links shared before the rename still open the same view.
 * Their labels are the panel's words (the catalogue's "controls" namespace, `<panel>.nI`).
 * @param {{ nI?: number, nT?: number, step?: number, aliases?: { nI?: string[], nT?: string[] } }} [options]
 * @returns {{ nI: NumberSpec, nT: NumberSpec }}
 */
export function indexPair({ nI = 1, nT = 1.5, step = 0.0001, aliases = {} } = {}) {
  return {
    nI: { type: 'number', default: nI, ...INDEX_RANGE, step, aliases: aliases.nI },
    nT: { type: 'number', default: nT, ...INDEX_RANGE, step, aliases: aliases.nT },
  };
}

/**
 * { nT } for a medium lit from air (n_i = 1): a coat, a road, a pool. aliases: older keys (['n']).
 * @param {{ nT?: number, step?: number, aliases?: string[] }} options
 * @returns {{ nT: NumberSpec }}
 */
export function transmittedIndex({ nT = 1.5, step = 0.001, aliases }) {
  return { nT: { type: 'number', default: nT, ...INDEX_RANGE, step, aliases } };
}

/**
 * A button that swaps n_i and n_t (light leaving the denser side), named by the panel in the page's
 * language (the catalogue's panelsShared.swap: "Swap n_i ↔ n_t", or words of its own). No words here:
 * the schemas that import this module come with every page and its workers.
 * @param {import('../../host/panelContract.js').PanelContext<{ nI: NumberSpec, nT: NumberSpec }>} ctx
 * @param {import('lil-gui').default} folder
 * @param {string} name
 */
export function addSwap(ctx, folder, name) {
  return ctx.tie(folder.add({ swap: () => ctx.set({ nI: ctx.values.nT, nT: ctx.values.nI }) }, 'swap').name(name), ['nI', 'nT']);
}
