// Parameters of the `normal-mips` panel: controls, URL keys and messages all use them. Pure data
// (no DOM), loaded with the page so the panel's link and state work before its module arrives.
import { TECHNIQUE_NAMES } from '../../normals/techniqueLayout.js';

export const schema = {
  map: {
    type: 'enum', default: 'bumps', label: 'Normal map',
    options: { bumps: 'Bumps', grooves: 'V-grooves', checker: 'Slope checker', noise: 'Value noise', mixed: 'Mixed' },
  },
  frequency: { type: 'number', default: 16, min: 2, max: 64, step: 2, label: 'Features per tile' },
  angle: { type: 'number', default: 35, min: 5, max: 60, step: 1, label: 'Steepest slope °' },
  size: { type: 'enum', default: '256', options: ['64', '128', '256', '512', '1024'], label: 'Texture size' },
  technique: { type: 'enum', default: 'toksvig', options: TECHNIQUE_NAMES, label: 'Technique' },
  alpha: { type: 'number', default: 0.2, min: 0.02, max: 1, step: 0.005, label: 'Base roughness α' },
  precision: {
    type: 'enum', default: 'f16', options: { u8: '8-bit unorm', f16: '16-bit float', f32: '32-bit float' }, label: 'Storage precision',
  },
  channels: { type: 'enum', default: '3', options: ['3', '2'], label: 'Channels (2: z rebuilt)' },
  level: { type: 'number', integer: true, default: -1, min: -1, max: 10, step: 1, label: 'Mip level (−1: auto)' },
  anisotropy: { type: 'enum', default: '1', options: ['1', '2', '4', '8', '16'], label: 'Anisotropic taps (1 = off)' },
  overlay: { type: 'boolean', default: false, label: 'Colour the mip level in use' },
  view: {
    type: 'enum', default: 'split', label: 'Picture',
    options: { split: 'Split', technique: 'Technique', truth: 'Ground truth', difference: 'Difference' },
  },
  viewEl: { type: 'number', default: 8, min: 2, max: 40, step: 0.5, label: 'View angle below horizon °' },
  lightEl: { type: 'number', default: 6, min: 1, max: 60, step: 0.5, label: 'Light elevation °' },
  lightAz: { type: 'number', default: 0, min: -90, max: 90, step: 1, label: 'Light azimuth ° (0 = ahead)' },
  lightDist: { type: 'number', default: 30, min: 3, max: 300, step: 1, label: 'Light distance (tiles)' },
  fresnel: {
    type: 'enum', default: 'exact', options: { exact: 'Exact', schlick: 'Schlick', off: 'Off (F = R0)' }, label: 'Fresnel (n = 1.5)',
  },
  texelLevel: { type: 'number', integer: true, default: 4, min: 0, max: 10, step: 1, label: 'Inspected level (or click the strip)' },
  texelX: { type: 'number', integer: true, default: 0, min: 0, max: 1023, step: 1, label: 'Inspected texel i' },
  texelY: { type: 'number', integer: true, default: 0, min: 0, max: 1023, step: 1, label: 'Inspected texel j' },
  truth: { type: 'boolean', default: true, label: 'Accumulate the ground truth' },
  truthSamples: { type: 'number', default: 128, min: 32, max: 2048, step: 16, label: 'Ground-truth samples per pixel' },
};
