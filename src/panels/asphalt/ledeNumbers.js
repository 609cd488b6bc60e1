// The numbers the panel's lede states (locales/en.json, panels → asphalt.lede), each in the words
// around it, from the physics that draws the road at its default values: tests/unit/teachingText.test.js
// fails where the lede says other numbers, or more. Not part of the panel's module (nothing imports it).
import { defaults } from '../../host/params.js';
import { fixed } from '../../ui/format.js';
import { SCENE, sheenGrowth, specularAlbedo } from './physics.js';
import { schema } from './schema.js';

/** @returns {string[]} */
export function ledeNumbers() {
  const values = defaults(schema);
  const growth = sheenGrowth(values, 2); // any view with the horizon in it gives the same factors
  const sun = `with the sun ${fixed(values.sunEl, 0)}° up`;
  return [
    `From the road straight below you to the road at the horizon, ${sun}`,
    `makes the specular light about ${fixed(growth.lobe, 0)}× brighter`,
    `and the half-vector rises about ${fixed(growth.fresnel, 0)}×`,
    `${sun} the road reflects only about ${fixed(100 * specularAlbedo(values), 0)} % of the sunlight specularly`,
    `diffuse albedo of ${fixed(100 * SCENE.albedo, 0)} %`,
  ];
}
