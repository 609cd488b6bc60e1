// Material presets built from materials.json (refractiveindex.info, CC0; cite Polyanskiy,
// Scientific Data 11, 94 (2024)). Each entry keeps its source so the UI can show it.
import data from './materials.json' with { type: 'json' };
import { conductorNormalIncidence, criticalAngle, normalIncidence } from './fresnel.js';

export const MATERIALS_ABOUT = data.about;
export const REFERENCE_NM = '589'; // sodium D line, the usual "refractive index" of a material

/**
 * A dielectric: n at 589 nm, and spectrum, n by wavelength in nm (as text: '450') where the data has them.
 * @typedef {Readonly<{ id: string, name: string, n: number, spectrum: Readonly<Record<string, number | undefined>>,
 *   source: string }>} Dielectric
 */
/**
 * A conductor: n + ik per RGB channel, at the wavelengths rgbNm.
 * @typedef {Readonly<{ id: string, name: string, rgbNm: readonly number[], n: readonly number[], k: readonly number[],
 *   source: string }>} Metal
 */

/**
 * Dielectrics with n at 589 nm (and at the other wavelengths where the data has them).
 * @type {Dielectric[]}
 */
export const dielectrics = data.dielectrics.map((entry) => Object.freeze({
  id: entry.id,
  name: entry.name,
  n: entry.n[REFERENCE_NM],
  spectrum: Object.freeze({ ...entry.n }),
  source: entry.source,
}));

/**
 * Conductors with complex index n + ik per RGB channel (650, 550, 450 nm).
 * @type {Metal[]}
 */
export const metals = data.metals.map((entry) => Object.freeze({
  id: entry.id,
  name: entry.name,
  rgbNm: Object.freeze([...entry.rgbNm]),
  n: Object.freeze([...entry.n]),
  k: Object.freeze([...entry.k]),
  source: entry.source,
}));

/**
 * @param {unknown} id
 */
export function dielectricById(id) {
  return dielectrics.find((m) => m.id === id) ?? null;
}

/**
 * @param {unknown} id
 */
export function metalById(id) {
  return metals.find((m) => m.id === id) ?? null;
}

/**
 * The group index n_g = n − λ dn/dλ at 589 nm, the speed of a pulse being c/n_g (Hecht, Optics,
 * 5th ed., §7.2), with dn/dλ the slope at 589 nm of the parabola through the data at 550, 589 and
 * 650 nm. Null where the data has no dispersion (one wavelength, or the same n at all of them).
 * @param {Readonly<Record<string, number | undefined>> | undefined} spectrum
 */
export function groupIndex(spectrum) {
  const [a, b, c] = ['550', REFERENCE_NM, '650'].map((nm) => spectrum?.[nm]);
  if (typeof a !== 'number' || typeof b !== 'number' || typeof c !== 'number' || (a === b && b === c)) return null;
  const [x0, x1, x2] = [550, 589, 650];
  // Derivative at x1 of the Lagrange parabola through (x0, a), (x1, b), (x2, c).
  const slope = (a * (x1 - x2)) / ((x0 - x1) * (x0 - x2))
    + (b * (2 * x1 - x0 - x2)) / ((x1 - x0) * (x1 - x2))
    + (c * (x1 - x0)) / ((x2 - x0) * (x2 - x1));
  return b - x1 * slope;
}

/**
 * Table row for a dielectric seen from air: the phase speed c/n and, where the data has dispersion,
 * the group speed c/n_g (as fractions of c), R0, critical angle.
 * @param {Dielectric} material
 */
export function dielectricSummary(material, outside = 1) {
  const n = material.n;
  const ng = groupIndex(material.spectrum);
  return {
    ...material,
    speed: 1 / n,
    groupSpeed: ng === null ? null : 1 / ng,
    r0: normalIncidence(outside, n),
    criticalAngle: criticalAngle(n, outside),
  };
}

/**
 * F0 per RGB channel of a metal: ((n − 1)² + k²)/((n + 1)² + k²).
 * @param {Metal} material
 */
export function metalF0(material) {
  return material.n.map((n, i) => conductorNormalIncidence(n, material.k[i]));
}
