// @ts-check
// Parameters of the `normal-mips` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { TECHNIQUES } from '../../normals/techniques.js';

/** @satisfies {import('../../host/panelContract.js').Schema} */
export const schema = {
  map: {
    type: 'enum', default: 'bumps',
    options: ['bumps', 'grooves', 'checker', 'noise', 'mixed'],
  },
  frequency: { type: 'number', default: 16, min: 2, max: 64, step: 2 },
  angle: { type: 'number', default: 35, min: 5, max: 60, step: 1 },
  size: { type: 'enum', default: '256', options: ['64', '128', '256', '512', '1024'] },
  technique: { type: 'enum', default: 'toksvig', options: [...TECHNIQUES] },
  alpha: { type: 'number', default: 0.2, min: 0.02, max: 1, step: 0.005 },
  precision: {
    type: 'enum', default: 'f16', options: ['u8', 'f16', 'f32'],
  },
  channels: { type: 'enum', default: '3', options: ['3', '2'] },
  level: { type: 'number', integer: true, default: -1, min: -1, max: 10, step: 1 },
  anisotropy: { type: 'enum', default: '1', options: ['1', '2', '4', '8', '16'] },
  overlay: { type: 'boolean', default: false },
  view: {
    type: 'enum', default: 'split',
    options: ['split', 'technique', 'truth', 'difference'],
  },
  viewEl: { type: 'number', default: 8, min: 2, max: 40, step: 0.5 },
  lightEl: { type: 'number', default: 6, min: 1, max: 60, step: 0.5 },
  lightAz: { type: 'number', default: 0, min: -90, max: 90, step: 1 },
  lightDist: { type: 'number', default: 30, min: 3, max: 300, step: 1 },
  fresnel: {
    type: 'enum', default: 'exact', options: ['exact', 'schlick', 'off'],
  },
  texelLevel: { type: 'number', integer: true, default: 4, min: 0, max: 10, step: 1 },
  texelX: { type: 'number', integer: true, default: 0, min: 0, max: 1023, step: 1 },
  texelY: { type: 'number', integer: true, default: 0, min: 0, max: 1023, step: 1 },
  truth: { type: 'boolean', default: true },
  truthSamples: { type: 'number', default: 128, min: 32, max: 2048, step: 16 },
};
