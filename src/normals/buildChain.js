// Mip chains, technique by technique: each level holds exactly what the technique stores
// (techniqueLayout.js), quantized to the chosen precision, as float32 values the shader reads.
// Every level is derived from the float32 moment pyramid (box averages of level 0) and quantized
// once, as an offline baker does (Filament's mipgen builds every level from level 0:
// libs/image/src/ImageSampler.cpp); a GPU glGenerateMipmap on RGBA8 would round again at every
// level (its levels come from repeated reduction, glGenerateMipmap reference page), which is not
// emulated.
import { buildMomentPyramid, PYRAMID_LAYOUT } from './momentPyramid.js';
import { checkPrecision, quantizeInPlace } from './storagePrecision.js';
import { checkChannels, TECHNIQUES, techniqueLayout } from './techniqueLayout.js';

const W = PYRAMID_LAYOUT.length;

/** The largest |b| component of level 0: the scale of LEAN/CLEAN's 8-bit ranges (1 if flat). */
export function slopeScaleOf(pyramid) {
  const d = pyramid[0].data;
  let S = 0;
  for (let o = 0; o < d.length; o += W) S = Math.max(S, Math.abs(d[o + 3]), Math.abs(d[o + 4]));
  return S > 0 ? S : 1;
}

// Fill the stored channels of every texel of one level from its pyramid data p (n texels into
// out, cw values per texel). One small function per technique keeps each loop monomorphic,
// which is several times faster in V8 than one loop that branches on the technique.
function fillNormal(p, n, out, cw) {
  for (let t = 0, o = 0, q = 0; t < n; t++, o += W, q += cw) {
    out[q] = p[o];
    out[q + 1] = p[o + 1];
    if (cw === 3) out[q + 2] = p[o + 2];
  }
}

// The unit direction (flat where the mean vanishes); with r = true, |N_a| goes in the last channel.
function fillUnit(p, n, out, cw, r) {
  const zc = r ? cw - 1 : cw;
  for (let t = 0, o = 0, q = 0; t < n; t++, o += W, q += cw) {
    const x = p[o];
    const y = p[o + 1];
    const z = p[o + 2];
    const len = Math.sqrt(x * x + y * y + z * z);
    const inv = len > 0 ? 1 / len : 0;
    out[q] = x * inv;
    out[q + 1] = y * inv;
    if (zc === 3) out[q + 2] = len > 0 ? z * inv : 1;
    if (r) out[q + zc] = len;
  }
}

function fillLean(p, n, out) {
  for (let t = 0, o = 0, q = 0; t < n; t++, o += W, q += 5) {
    out[q] = p[o + 3];
    out[q + 1] = p[o + 4];
    out[q + 2] = p[o + 5];
    out[q + 3] = p[o + 6];
    out[q + 4] = p[o + 7];
  }
}

function fillClean(p, n, out) {
  for (let t = 0, o = 0, q = 0; t < n; t++, o += W, q += 3) {
    out[q] = p[o + 3];
    out[q + 1] = p[o + 4];
    out[q + 2] = p[o + 5] + p[o + 6];
  }
}

const FILL = {
  naive: fillNormal,
  toksvig: fillNormal,
  renormalized: (p, n, out, cw) => fillUnit(p, n, out, cw, false),
  vmf: (p, n, out, cw) => fillUnit(p, n, out, cw, true),
  lean: fillLean,
  clean: fillClean,
};

/**
 * buildChain(pyramid, technique, { precision = 'f32', channels = 3 }) →
 * { technique, precision, channels, size, slopeScale, layout, textures, components,
 *   levels: [{ level, size, data: Float32Array(size² · components) }] }.
 * layout/textures are techniqueLayout's; data is interleaved in layout order, row-major like
 * level 0 (sampleLevel0.js), values as read back after quantization.
 */
export function buildChain(pyramid, technique, { precision = 'f32', channels = 3 } = {}) {
  checkPrecision(precision);
  checkChannels(channels);
  const slopeScale = slopeScaleOf(pyramid);
  const { channels: layout, textures, usesNormalChannels } = techniqueLayout(technique, channels, slopeScale);
  const components = layout.length;
  const levels = pyramid.map(({ level, size, data: p }) => {
    const data = new Float32Array(size * size * components);
    FILL[technique](p, size * size, data, components);
    return { level, size, data: quantizeInPlace(data, layout, precision) };
  });
  return {
    technique,
    precision,
    channels: usesNormalChannels ? channels : null,
    size: pyramid[0].size,
    slopeScale,
    layout,
    textures,
    components,
    levels,
  };
}

/**
 * buildAllChains(normals, size, { precision = 'f32', channels = 3, components = 3 }) →
 * { pyramid, chains: { naive, renormalized, toksvig, lean, clean, vmf } } from a level-0 normal
 * array (sampleLevel0's layout, `components` values per texel). Toksvig stores exactly what naive
 * stores, so its chain shares naive's level arrays (treat them as read-only).
 */
export function buildAllChains(normals, size, { precision = 'f32', channels = 3, components = 3 } = {}) {
  const pyramid = buildMomentPyramid(normals, size, { components });
  const chains = {};
  for (const technique of TECHNIQUES) {
    chains[technique] = technique === 'toksvig'
      ? { ...chains.naive, technique }
      : buildChain(pyramid, technique, { precision, channels });
  }
  return { pyramid, chains };
}
