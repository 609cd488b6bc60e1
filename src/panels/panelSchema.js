// @ts-check
// Every panel's schema by id, without the panel's module: pure data that comes with every page, so
// a link, a message or a homework sheet's start state can be checked before any panel loads.
const schemas = /** @type {Record<string, import('../host/panelContract.js').Schema>} */ (
  import.meta.glob('./*/schema.js', { eager: true, import: 'schema' }));

/**
 * The schema of panel `id`, or undefined. Looked up as an own key only: an id from a link or a
 * sheet such as `constructor` finds nothing inherited.
 * @param {string} id
 * @returns {import('../host/panelContract.js').Schema | undefined}
 */
export function panelSchema(id) {
  const path = `./${id}/schema.js`;
  return Object.hasOwn(schemas, path) ? schemas[path] : undefined;
}
