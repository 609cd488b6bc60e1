// The numbers the panel's lede states (locales/en.json, panels → refractive-index.lede), each in the
// words around it, from the materials' data and the optics core: tests/unit/teachingText.test.js
// fails where the lede says other numbers, or more. Not part of the panel's module (nothing imports it).
import { normalIncidence } from '../../optics/fresnel.js';
import { dielectricById } from '../../optics/materials.js';
import { fixed } from '../../ui/format.js';

/** @returns {string[]} */
export function ledeNumbers() {
  const glass = Math.round(dielectricById('glass').n * 10) / 10; // "about": crown glass to one decimal
  const water = dielectricById('water').n;
  return [
    `glass is about ${fixed(glass, 1)}`,
    `glass of ${fixed(glass, 1)} reflects ${fixed(normalIncidence(1, glass), 2)} head-on in air `
      + `but ${fixed(normalIncidence(water, glass), 4)} under water`,
  ];
}
