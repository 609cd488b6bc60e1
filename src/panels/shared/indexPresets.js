// Refractive-index presets for a dropdown: the lecture's round values, then the measured
// dielectrics at 589 nm from the materials data, then "custom". The preset shown is derived
// from the index, so the URL holds only the index and can never contradict itself.
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';
import { dielectrics } from '../../optics/materials.js';
import { hasMaterialName, materialName } from './materialName.js';
import { indexText } from './indexText.js';

const t = messages('panelsShared', english);

// Their names are read when the options are made (the page's language is set after modules load).
const LECTURE_VALUES = [
  { id: 'vacuum', name: () => t('presetVacuum'), n: 1 },
  { id: 'glass-1.5', name: () => t('presetGlassLecture'), n: 1.5 },
];

/** A preset's name: a material of materials.json by the catalogue's name, else its own (text, or a function giving it). */
const nameOf = (m) => (hasMaterialName(m.id) ? materialName(m.id) : typeof m.name === 'function' ? m.name() : m.name);

/**
 * list: the presets to offer (the lecture's values and the measured dielectrics by default).
 * @param {{ id: string, n: number, name?: string | (() => string) }[]} [list]
 */
export function indexPresets(list = [...LECTURE_VALUES, ...dielectrics]) {
  const options = Object.fromEntries(list.map((m) => [t('presetOption', { name: nameOf(m), n: indexText(m.n) }), m.id]));
  options[t('presetCustom')] = 'custom';
  return {
    options,
    index: (presetId) => list.find((m) => m.id === presetId)?.n,
    idFor: (n) => list.find((m) => Math.abs(m.n - n) < 5e-7)?.id ?? 'custom',
  };
}
