// Storage cost of a whole mip chain per technique × precision × channels:
// bytes = texels in the chain × stored channels × bytes per channel, and uploadBytes with the
// RGBA padding the textures actually get (techniqueLayout.js). GPU drivers may add their own
// alignment; that is not modelled.
import { chainTexelCount, levelCount } from './momentPyramid.js';
import { checkPrecision, PRECISIONS } from './storagePrecision.js';
import { TECHNIQUES, techniqueLayout } from './techniqueLayout.js';

// Whether the footprint's normal variance reaches the shader at all: renormalizing, or rebuilding
// z from 2 channels, makes |N| = 1 (Toksvig 2004; Hill, "Specular Showdown", 2011).
function varianceKept(technique, channels) {
  if (technique === 'naive' || technique === 'renormalized') return false;
  if (technique === 'toksvig') return channels === 3; // 2 channels: |N| = 1, σ² = 0
  return true;
}

/**
 * storageCost({ technique, precision, channels = 3, size }) →
 * { technique, precision, channels, size, levels, texels, components, bytes, uploadComponents,
 *   uploadBytes, formats: ['RGBA', …], varianceKept }.
 */
export function storageCost({ technique, precision, channels = 3, size }) {
  checkPrecision(precision);
  const layout = techniqueLayout(technique, channels);
  const texels = chainTexelCount(size);
  const bytesPer = PRECISIONS[precision].bytes;
  const components = layout.channels.length;
  const uploadComponents = layout.textures.reduce((sum, t) => sum + t.sources.length, 0);
  return {
    technique,
    precision,
    channels: layout.usesNormalChannels ? channels : null,
    size,
    levels: levelCount(size),
    texels,
    components,
    bytes: texels * components * bytesPer,
    uploadComponents,
    uploadBytes: texels * uploadComponents * bytesPer,
    formats: layout.textures.map((t) => t.format),
    varianceKept: varianceKept(technique, channels),
  };
}

/** Every technique × precision × channels combination for one size (LEAN/CLEAN once each). */
export function storageTable(size) {
  const rows = [];
  for (const technique of TECHNIQUES) {
    for (const precision of Object.keys(PRECISIONS)) {
      const channelOptions = techniqueLayout(technique).usesNormalChannels ? [3, 2] : [3];
      for (const channels of channelOptions) rows.push(storageCost({ technique, precision, channels, size }));
    }
  }
  return rows;
}
