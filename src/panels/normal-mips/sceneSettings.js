// @ts-check
// What the normal-mips panel's controls mean for its GPU scene and its chain builds: the light's
// place, the normal map's parameters, the uniforms of one frame and which keys touch what. Pure,
// so the runs (runs.js) and their tests use the same numbers the picture gets.
import { createNormalMap } from '../../normals/createNormalMap.js';
import { mapUniforms } from '../../normals/mapUniforms.js';
import { DEG } from '../../optics/angles.js';

export const IOR = 1.5;
// Camera: height 1 above the plane, one tile per world unit (the scene's uCamHeight and uTile).
export const CAM_HEIGHT = 1;

export const CHAIN_KEYS = ['map', 'frequency', 'angle', 'size', 'precision', 'channels'];
export const LIGHT_KEYS = ['viewEl', 'lightEl', 'lightAz', 'lightDist'];
export const SHIMMER_KEYS = [...CHAIN_KEYS, ...LIGHT_KEYS, 'alpha', 'level', 'anisotropy', 'fresnel'];
export const INSPECT_KEYS = ['texelLevel', 'texelX', 'texelY'];
export const TRUTH_KEYS = [...LIGHT_KEYS, 'map', 'frequency', 'angle', 'alpha', 'fresnel', 'truth', 'truthSamples'];
/** Keys that change what the techniques store or how they are sampled, but not the ground truth. */
export const ERROR_KEYS = ['size', 'precision', 'channels', 'level', 'anisotropy'];

/** A test of a change: has(list) is true when keys (null or undefined: all) name any key of list. */
export function touches(/** @type {string[] | null | undefined} */ keys) {
  const changed = keys ? new Set(keys) : null;
  return (/** @type {string[]} */ list) => !changed || list.some((k) => changed.has(k));
}

/**
 * The point light's world position: lightDist tiles from the view centre (where the middle of the
 * picture meets the plane) in the direction (azimuth, elevation); with azimuth 0 it is straight
 * ahead, so its mirror highlight runs towards the viewer. fromCamera: the unit direction to it
 * from the camera at (0, CAM_HEIGHT, 0).
 * @param {{ viewEl: number, lightEl: number, lightAz: number, lightDist: number }} values
 */
export function lightPlacement({ viewEl, lightEl, lightAz, lightDist }) {
  const centre = [0, 0, CAM_HEIGHT / Math.tan(viewEl * DEG)];
  const dir = [
    Math.sin(lightAz * DEG) * Math.cos(lightEl * DEG), Math.sin(lightEl * DEG), Math.cos(lightAz * DEG) * Math.cos(lightEl * DEG),
  ];
  const position = centre.map((c, k) => c + lightDist * dir[k]);
  const toLight = [position[0], position[1] - CAM_HEIGHT, position[2]];
  const length = Math.hypot(...toLight);
  return { position, fromCamera: toLight.map((c) => c / length) };
}

// Value noise: octave o adds a slope component of at most 3.75·amplitude·gain^o
// (createValueNoise.js), so over 3 octaves of gain ½ the steepest is 3.75·1.75·amplitude: the
// angle control sets that bound. Its base lattice is half the feature count, so the finest octave
// has twice as many cells as the control says.
const noiseAmplitude = (/** @type {number} */ angleDeg) => Math.tan(angleDeg * DEG) / (3.75 * 1.75);

/**
 * createNormalMap parameters for the controls (the GLSL twin gets the same via mapUniforms).
 * @param {{ map: string, frequency: number, angle: number }} values
 */
export function mapParams({ map, frequency, angle }) {
  if (map === 'bumps') return { frequency, edgeAngleDeg: angle };
  if (map === 'grooves') return { frequency, angleDeg: angle, profile: 'v', direction: 'u' };
  if (map === 'noise') return { frequency: Math.max(1, frequency / 2), amplitude: noiseAmplitude(angle) };
  if (map === 'mixed') {
    // 4 × 4 blocks; bumps and noise at blocks·f per tile, grooves at 2×, the checker at 4× that.
    return {
      blocks: 4, frequency: Math.max(1, Math.round(frequency / 8)), angleDeg: angle, edgeAngleDeg: angle, amplitude: noiseAmplitude(angle),
    };
  }
  return { frequency: 2 * Math.max(1, Math.round(frequency / 2)), angleDeg: angle }; // the checker tiles only with even counts
}

/** What the chain builder is asked for (createChainBuilder's request). */
export function chainRequest(/** @type {any} */ values) {
  return {
    kind: values.map, params: mapParams(values), size: Number(values.size), precision: values.precision, channels: Number(values.channels),
  };
}

/**
 * Keys still to apply after a build: undefined (none waiting) merged with keys (null: all).
 * @param {string[] | null | undefined} pending
 * @param {string[] | null | undefined} keys
 * @returns {string[] | null}
 */
export function mergeKeys(pending, keys) {
  if (pending === undefined) return keys ?? null;
  return pending === null || !keys ? null : [...pending, ...keys];
}

/** The uniforms the scene starts with, before the first settings are applied. */
export function initialUniforms(/** @type {any} */ values) {
  return {
    uCamHeight: CAM_HEIGHT, uPitch: 0.1, uTanHalfFov: Math.tan(18 * DEG), uTile: 1, uLightPower: 5, uIor: IOR,
    uFresnel: 0, uKd: 0.05, uAlpha: 0.1, uForcedLevel: -1, uMapSize: 256, uMaxLevel: 8, uAniso: 1,
    ...mapUniforms(createNormalMap(values.map, mapParams(values))), uSunDir: [0, 0.1, 1],
    uLightPos: [0, 3, 37], uLightDist2: 900, uView: 0, uOverlay: 0, uDiffScale: 0.25,
  };
}

/**
 * The scene's settings for the controls (createNormalMipsScene's set()). levels: the chain's
 * mip level count; anisotropy: the taps in use (what was asked for, as far as the GPU offers).
 */
export function sceneSettings(/** @type {any} */ values, { levels, anisotropy }) {
  const light = lightPlacement(values);
  return {
    technique: values.technique,
    channels: Number(values.channels),
    cap: values.truthSamples,
    truthOn: values.truth,
    anisotropy,
    uAlpha: values.alpha,
    uForcedLevel: values.level < 0 ? -1 : Math.min(values.level, levels - 1),
    uMapSize: Number(values.size),
    uMaxLevel: levels - 1,
    ...mapUniforms(createNormalMap(values.map, mapParams(values))),
    uPitch: values.viewEl * DEG,
    uLightPos: light.position,
    uLightDist2: values.lightDist ** 2,
    uSunDir: light.fromCamera, // the sky draws its glow where the light is
    uFresnel: ['exact', 'schlick', 'off'].indexOf(values.fresnel),
    uView: values.truth ? ['split', 'technique', 'truth', 'difference'].indexOf(values.view) : 1,
    uOverlay: values.overlay ? 1 : 0,
  };
}
