// @ts-check
// What the asphalt panel says: its key numbers, the hover readout and the description, from the
// float64 scene (physics.js), in the page's language. Pure (no DOM), so tests/unit/asphaltWords.test.js
// reads every sentence the panel can show.
import english from 'virtual:messages/en/asphalt';
import { messages } from '../../i18n/messages.js';
import { fixed, rounded, sci, tickLabel } from '../../ui/format.js';
import { normalIncidence } from '../../optics/fresnel.js';
import { SCENE, lambertianEquivalent } from './physics.js';
import { schema } from './schema.js';
import { indexText } from '../shared/indexText.js';

const t = messages('asphalt', english);
const SHOWN = 3; // decimals of every luminance and F the panel shows
const f3 = (/** @type {number} */ x) => fixed(x, SHOWN);
const deg = (/** @type {number} */ x) => `${fixed(x, 1)}°`;
const percent = (/** @type {number} */ x) => `${fixed(100 * x, 1)} %`;
const times = (/** @type {number} */ x) => `×${fixed(x, 1)}`;
// Reflected light is called concentrated where, from its brightest direction, it is at least this many
// times as bright as a matte road reflecting the same share of the sunlight.
const CONCENTRATED = 3;

/**
 * 'horizon' where a spot `below` degrees below the horizon shows as 0.0°: the sight line grazes the
 * road towards the horizon (a line along the road never meets it; the spot is the limit there).
 * @param {number} below
 */
const whereBelow = (below) => (deg(below) === deg(0) ? 'horizon' : 'below');

/** @typedef {import('./physics.js').RoadValues & { camEl: number }} Values */
/** @typedef {import('./physics.js').Shade} Shade */
/**
 * What the words are made of: the view's brightest spot and centre (highlightInView), the growth against
 * the road straight below (sheenGrowth), the specular albedo, and the brightest sight line from any camera.
 * @typedef {{ values: Values, peak: Shade, centre: Shade, growth: ReturnType<typeof import('./physics.js').sheenGrowth>,
 *   albedo: number, brightest: { below: number, specular: number } }} Road
 */

/**
 * Whether the road shows no specular reflection at all: the sun's highlight reads 0 at the shown decimals
 * from every direction (n_t = 1, where F = 0 at every angle, or an index so near 1 that it rounds so).
 * @param {Road} road
 */
export const noReflection = (road) => rounded(road.brightest.specular, SHOWN) === 0;

/**
 * How concentrated the specular light is: the brightest sight line's luminance against a matte
 * (Lambertian) road that reflected the same share of the sunlight evenly in every direction.
 * @param {Road} road
 */
export const concentration = (road) => road.brightest.specular / lambertianEquivalent(road.albedo, road.values.sunEl);

/**
 * The hover readout for a spot of road, or the sky's.
 * @param {Shade | null} hit
 */
export function readoutText(hit) {
  if (!hit) return t('readoutSky');
  return t('readoutRoad', {
    distance: fixed(hit.distance, 1), below: deg(hit.below), thetaD: deg(hit.thetaD), F: f3(hit.F), specular: f3(hit.specular),
    diffuse: f3(hit.diffuse),
  });
}

/**
 * Why there is no specular reflection, as a clause: n_t = 1 matches air; with Fresnel off, F held at
 * a near-0 R0 (the switch, not the index, keeps the grazing rise away); else a near-1 index that
 * rounds to nothing even at grazing.
 */
const noneClause = (/** @type {Road} */ road) => {
  const { nT, fresnel } = road.values;
  return {
    matched: nT === 1 ? 'yes' : fresnel ? 'no' : 'off', nT: indexText(nT), zero: f3(0), r0: sci(normalIncidence(1, nT), 1),
  };
};

/**
 * The key numbers: [term, value, key?] rows.
 * @param {Road} road
 * @returns {[string, string, boolean?][]}
 */
export function summaryRows(road) {
  const { values, peak, centre, growth, albedo } = road;
  const r0 = normalIncidence(1, values.nT);
  /** @type {[string, string, boolean?][]} */
  const head = [[t('summary.centre'), t('summary.centreValue', { F: f3(centre.F), thetaD: deg(centre.thetaD) }), true]];
  const shares = t('summary.albedoValue', { albedo: percent(albedo), diffuse: percent(SCENE.albedo) });
  /** @type {[string, string, boolean?][]} */
  const tail = [[t('summary.albedo', { sunEl: deg(values.sunEl) }), shares], [t('summary.r0'), f3(r0)]];
  if (noReflection(road)) {
    // No highlight to name, nor a ratio to it: a sentence, and the diffuse road, which looks the same from everywhere.
    const none = t('summary.noneValue', noneClause(road));
    return [...head, [t('summary.none'), none, true], [t('summary.diffuseAll'), f3(peak.diffuse)], ...tail];
  }
  return [
    ...head,
    [t('summary.peak'), t('summary.peakValue', {
      below: deg(peak.below), where: whereBelow(peak.below), specular: f3(peak.specular), thetaD: deg(peak.thetaD), F: f3(peak.F),
    }), true],
    [t('summary.diffuse'), f3(peak.diffuse)],
    [t('summary.ratio'), `${fixed(peak.specular / peak.diffuse, 1)}×`],
    [t('summary.growth'), t('summary.growthValue', {
      total: times(growth.total), lobe: times(growth.lobe), fresnel: times(growth.fresnel), overall: times(growth.overall),
    })],
    ...tail,
  ];
}

/**
 * The panel's description: its setting, then what the road does.
 * @param {Road} road
 */
export function describeRoad(road) {
  const { values, peak, centre, growth, albedo, brightest } = road;
  // A control's value as a sentence writes it: the decimals of its step; the index with every digit it has.
  const shown = (/** @type {'camEl' | 'sunEl' | 'roughness'} */ key) => tickLabel(values[key], schema[key].step);
  const setting = t('describeSetting', {
    camEl: shown('camEl'), sunEl: shown('sunEl'), roughness: shown('roughness'), nT: indexText(values.nT),
    fresnel: values.fresnel ? 'on' : 'off',
  });
  if (noReflection(road)) return `${setting} ${t('describeNone', { ...noneClause(road), diffuse: f3(peak.diffuse) })}`;
  const factor = concentration(road);
  const shape = t(factor >= CONCENTRATED ? 'shapeConcentrated' : 'shapeSpread', {
    concentration: fixed(factor, 1), below: deg(brightest.below),
    where: whereBelow(brightest.below),
  });
  const ratio = albedo / SCENE.albedo;
  return `${setting} ${t('describe', {
    thetaD: deg(centre.thetaD),
    F: f3(centre.F),
    below: deg(peak.below),
    where: whereBelow(peak.below),
    specular: f3(peak.specular),
    ratio: fixed(peak.specular / peak.diffuse, 1),
    diffuse: f3(peak.diffuse),
    total: times(growth.total),
    lobe: times(growth.lobe),
    fresnel: times(growth.fresnel),
    overall: times(growth.overall),
    albedo: percent(albedo),
    share: ratio < 0.95 ? 'less' : ratio <= 1.05 ? 'about' : 'more',
    albedoDiffuse: percent(SCENE.albedo),
    times: fixed(ratio, 2),
    shape,
  })}`;
}
