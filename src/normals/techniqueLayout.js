// What each technique stores per texel, and how it is packed into WebGL2 textures.
//   naive         N_a, the box average, not renormalized (what glGenerateMipmap makes with the
//                 box filter its reference page recommends)
//   renormalized  N_a/|N_a| (what "most algorithms" do: Toksvig, "Mipmapping Normal Maps", NVIDIA 2004)
//   toksvig       N_a, as naive: the shader reads σ² from |N_a| (runtime Toksvig, Toksvig 2004)
//   vmf           N_a/|N_a| plus r̄ = |N_a| in its own channel, baked from float data before
//                 quantization (MJP's "precomputed vMF" in TheRealMJP/SpecularAA and Filament's
//                 tools/roughness-prefilter bake a channel; Han et al., "Frequency Domain Normal
//                 Map Filtering", SIGGRAPH 2007); r̄ is kept rather than α' so the base α stays a
//                 live control
//   lean          B = (bx, by), M = (mxx, myy, mxy): 5 scalars in 2 textures (Olano & Baker,
//                 "LEAN Mapping", I3D 2010)
//   clean         B = (bx, by), M = mxx + myy: 3 scalars (Baker, "Spectacular Specular – LEAN and
//                 CLEAN Specular Highlights", GDC 2011)
// channels = 2 stores only x, y of a normal (z = √(1 − x² − y²) in the shader: BC5-style, which
// Toksvig cannot use: Hill, "Specular Showdown in the Wild West", 2011),
// so |N| = 1 and runtime Toksvig sees no variance at all. LEAN and CLEAN store slopes, never
// z, so channels does not apply to them.
// Each channel has the range [min, max] an 8-bit unorm code c ∈ {0..255} spans: value =
// min + (max − min)·c/255. Normals use the usual affine encoding c = n/2 + ½. Slope moments use a
// scale S (the largest |b| component of level 0), like the "LEAN scale factor" of MJP's
// SpecularAA sample (TheRealMJP/SpecularAA).
// 3-channel data is padded to RGBA: textures are RGBA, RG or R only (createMipTexture.js), the
// layouts the upload and its read-back test (every level sampled exactly) cover.

import { TECHNIQUES } from './techniques.js';

export { TECHNIQUES };

function normalChannels(channels) {
  const names = channels === 3 ? ['x', 'y', 'z'] : ['x', 'y'];
  return names.map((name) => ({ name, min: -1, max: 1 }));
}

function rgbaPadded(count, pad) {
  const sources = [0, 1, 2, 3].map((c) => (c < count ? c : { pad }));
  return { format: 'RGBA', sources };
}

export function checkTechnique(technique) {
  if (!TECHNIQUES.includes(technique)) {
    throw new RangeError(`technique must be one of ${TECHNIQUES.join(', ')}, got ${String(technique)}`);
  }
  return technique;
}

export function checkChannels(channels) {
  if (channels !== 2 && channels !== 3) throw new RangeError(`channels must be 2 or 3, got ${String(channels)}`);
  return channels;
}

/**
 * techniqueLayout(technique, channels = 3, slopeScale = 1) →
 * { channels: [{ name, min, max }], textures: [{ format: 'RGBA' | 'RG' | 'R', sources }],
 *   usesNormalChannels } where sources[k] is the stored channel index that goes to texture
 * component k, or { pad: value } for a padding component.
 */
export function techniqueLayout(technique, channels = 3, slopeScale = 1) {
  checkTechnique(technique);
  checkChannels(channels);
  const S = slopeScale;
  switch (technique) {
    case 'lean':
      return {
        channels: [
          { name: 'bx', min: -S, max: S },
          { name: 'by', min: -S, max: S },
          { name: 'mxx', min: 0, max: S * S },
          { name: 'myy', min: 0, max: S * S },
          { name: 'mxy', min: -S * S, max: S * S },
        ],
        textures: [{ format: 'RGBA', sources: [0, 1, 2, 3] }, { format: 'R', sources: [4] }],
        usesNormalChannels: false,
      };
    case 'clean':
      return {
        channels: [
          { name: 'bx', min: -S, max: S },
          { name: 'by', min: -S, max: S },
          { name: 'm', min: 0, max: 2 * S * S },
        ],
        textures: [rgbaPadded(3, 0)],
        usesNormalChannels: false,
      };
    case 'vmf': {
      const list = [...normalChannels(channels), { name: 'r', min: 0, max: 1 }];
      return { channels: list, textures: [rgbaPadded(list.length, 1)], usesNormalChannels: true };
    }
    default:
      return {
        channels: normalChannels(channels),
        textures: [channels === 3 ? rgbaPadded(3, 1) : { format: 'RG', sources: [0, 1] }],
        usesNormalChannels: true,
      };
  }
}
