// Refractive-index presets for a dropdown: the lecture's round values, then the measured
// dielectrics at 589 nm from the materials data, then "custom". The preset shown is derived
// from the index, so the URL holds only the index and can never contradict itself.
import { dielectrics } from '../../optics/materials.js';

const LECTURE_VALUES = [
  { id: 'vacuum', name: 'Vacuum', n: 1 },
  { id: 'glass-1.5', name: 'Glass (lecture)', n: 1.5 },
];

/** list: [{ id, name, n }] to offer (the lecture's values and the measured dielectrics by default). */
export function indexPresets(list = [...LECTURE_VALUES, ...dielectrics]) {
  const options = Object.fromEntries(list.map((m) => [`${m.name} (${m.n})`, m.id]));
  options.Custom = 'custom';
  return {
    options,
    index: (presetId) => list.find((m) => m.id === presetId)?.n,
    idFor: (n) => list.find((m) => Math.abs(m.n - n) < 5e-7)?.id ?? 'custom',
  };
}
