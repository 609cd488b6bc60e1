// Material presets built from materials.json (refractiveindex.info, CC0; cite Polyanskiy,
// Scientific Data 11, 94 (2024)). Each entry keeps its source so the UI can show it.
import data from './materials.json' with { type: 'json' };
import { conductorNormalIncidence, criticalAngle, normalIncidence } from './fresnel.js';

export const MATERIALS_ABOUT = data.about;
export const REFERENCE_NM = '589'; // sodium D line, the usual "refractive index" of a material

/** Dielectrics with n at 589 nm (and at the other wavelengths where the data has them). */
export const dielectrics = data.dielectrics.map((entry) => Object.freeze({
  id: entry.id,
  name: entry.name,
  n: entry.n[REFERENCE_NM],
  spectrum: Object.freeze({ ...entry.n }),
  source: entry.source,
}));

/** Conductors with complex index n + ik per RGB channel (650, 550, 450 nm). */
export const metals = data.metals.map((entry) => Object.freeze({
  id: entry.id,
  name: entry.name,
  rgbNm: Object.freeze([...entry.rgbNm]),
  n: Object.freeze([...entry.n]),
  k: Object.freeze([...entry.k]),
  source: entry.source,
}));

export function dielectricById(id) {
  return dielectrics.find((m) => m.id === id) ?? null;
}

export function metalById(id) {
  return metals.find((m) => m.id === id) ?? null;
}

/** Table row for a dielectric seen from air: speed c/n (as a fraction of c), R0, critical angle. */
export function dielectricSummary(material, outside = 1) {
  const n = material.n;
  return {
    ...material,
    speed: 1 / n,
    r0: normalIncidence(outside, n),
    criticalAngle: criticalAngle(n, outside),
  };
}

/** F0 per RGB channel of a metal: ((n − 1)² + k²)/((n + 1)² + k²). */
export function metalF0(material) {
  return material.n.map((n, i) => conductorNormalIncidence(n, material.k[i]));
}
