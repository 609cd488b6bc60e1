// @ts-check
// Loads a panel's module on demand (each panel is its own chunk, so an embed downloads only the
// panel it shows) and joins it with its manifest entry into the definition the host runs.
import { PANELS, panelEntry } from './manifest.js';

/** @typedef {{ schema?: import('../host/panelContract.js').Schema, mount?: import('../host/panelContract.js').PanelDefinition['mount'] }} PanelModule */
const modules = /** @type {Record<string, () => Promise<PanelModule>>} */ (import.meta.glob('./*/index.js'));
const moduleOf = (id) => modules[`./${id}/index.js`];

/** Manifest ids whose folder has no index.js: a build or test failure, never a silent omission. */
export const missingModules = PANELS.filter((p) => !moduleOf(p.id)).map((p) => p.id);

/**
 * The panel `id`: its manifest entry with the module's schema and mount (src/host/panelContract.js).
 * Throws, naming the panel, when the id is unknown or the module does not keep the contract.
 * @returns {Promise<import('../host/panelContract.js').PanelDefinition>}
 */
export async function loadPanel(id) {
  const entry = panelEntry(id);
  const load = moduleOf(id);
  if (!entry || !load) throw new Error(`There is no panel module src/panels/${id}/index.js in the manifest.`);
  const module = await load();
  if (typeof module.mount !== 'function' || !module.schema || typeof module.schema !== 'object') {
    throw new Error(`src/panels/${id}/index.js must export schema and mount().`);
  }
  return Object.freeze({ ...entry, schema: module.schema, mount: module.mount });
}
