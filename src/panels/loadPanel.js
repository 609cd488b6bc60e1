// @ts-check
// Panels for the host. A panel's schema (pure data) comes with the page, so every panel's link,
// values and messages work at once; its module (DOM, scene, shaders, libraries) is its own chunk,
// loaded only when the panel is about to be seen, so a page downloads only what it shows.
import { PANELS, panelEntry } from './manifest.js';
import { panelSchema } from './panelSchema.js';

/**
 * @typedef {{
 *   schema?: import('../host/panelContract.js').Schema,
 *   mount?: import('../host/panelContract.js').PanelDefinition['mount']
 * }} PanelModule
 */
const modules = /** @type {Record<string, () => Promise<PanelModule>>} */ (import.meta.glob('./*/index.js'));
/** @param {string} id */
const moduleOf = (id) => (Object.hasOwn(modules, `./${id}/index.js`) ? modules[`./${id}/index.js`] : undefined);

/** What the manifest's panels lack, in words (the build stops on the same): said on the page, never a silent omission. */
export const missingFiles = PANELS.flatMap(({ id }) => [
  ...(moduleOf(id) ? [] : [`The panel “${id}” has no module src/panels/${id}/index.js.`]),
  ...(panelSchema(id) ? [] : [`The panel “${id}” has no schema: src/panels/${id}/schema.js must export it.`]),
]);

/**
 * The module's mount(), checked: the module must keep the contract and export the same schema.
 * @param {string} id
 */
async function loadMount(id) {
  const load = moduleOf(id);
  const module = load ? await load() : undefined;
  if (typeof module?.mount !== 'function' || module.schema !== panelSchema(id)) {
    throw new Error(`src/panels/${id}/index.js must export mount() and the schema of its schema.js.`);
  }
  return module.mount;
}

/**
 * The panel `id` without its module yet: its manifest entry, its schema, and load(), which
 * resolves to its mount(). Throws, naming the panel, when the id is unknown.
 * @param {string} id
 * @returns {import('../host/panelContract.js').PanelDefinition}
 */
export function panelDefinition(id) {
  const entry = panelEntry(id);
  const schema = panelSchema(id);
  if (!entry) throw new Error(`There is no panel “${id}” in the manifest.`);
  if (!moduleOf(id)) throw new Error(`The panel “${id}” has no module src/panels/${id}/index.js.`);
  if (!schema || typeof schema !== 'object') throw new Error(`The panel “${id}” has no schema: src/panels/${id}/schema.js must export it.`);
  /** @type {ReturnType<typeof loadMount> | null} */
  let loading = null;
  return Object.freeze({ ...entry, schema, load: () => (loading ??= loadMount(id)) });
}

/**
 * The panel `id` with its module loaded: the definition the host runs at once (the embed page).
 * @param {string} id
 * @returns {Promise<import('../host/panelContract.js').PanelDefinition>}
 */
export async function loadPanel(id) {
  const definition = panelDefinition(id);
  const mount = await loadMount(id);
  return Object.freeze({ ...definition, mount });
}
