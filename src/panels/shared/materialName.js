// The names of the lab's materials (src/optics/materials.json) as users see them, in the page's
// language: the catalogue's "materials" namespace, keyed by each material's id in camelCase
// ("fused-silica" → fusedSilica). materials.json keeps its ids, which links and messages use, and
// its English names as data; what a table, a select, a swatch or a sentence shows comes from here.
import english from 'virtual:messages/en/materials';
import { messages } from '../../i18n/messages.js';

const t = messages('materials', english);
const keyOf = (id) => String(id).replace(/-([a-z])/g, (_, letter) => letter.toUpperCase());

const has = (key) => Object.hasOwn(english, key);

/** True when the catalogue names this material (a preset of a panel's own is not one). */
export const hasMaterialName = (id) => has(keyOf(id));

/** A material's name as a table row, an option or a swatch shows it: "Water (20 °C)", "Gold". */
export const materialName = (id) => t(keyOf(id));

/** Its name inside a sentence ("for gold it is close"), where a language writes it otherwise; else its name. */
export function materialNameInText(id) {
  const key = `${keyOf(id)}.inText`;
  return has(key) ? t(key) : materialName(id);
}
