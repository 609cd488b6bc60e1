// Typed arrays ready for upload: one entry per texture of the technique, each with a `mipmaps`
// array ([{ data, width, height }], level 0 first, down to 1×1) that createMipTexture.js uploads
// level by level (no generateMipmap). Format 'RGBA' | 'RG' | 'R' and type 'u8' | 'f16' | 'f32' map
// to RGBA8 / RG8 / R8, RGBA16F … and RGBA32F …: linear formats, never SRGB8_ALPHA8, which would
// decode the vectors as colours. u8 decodes in the shader as value = min + (max − min)·c using
// `ranges` (per texture component).
import { halfBits, halfBitsOfFloat32Bits } from './float16Bits.js';
import { encodeUnorm8 } from './storagePrecision.js';

// One component at a time (stride w in the output), one small function per output type, so that
// each loop sees one typed-array kind (V8 optimizes a monomorphic loop several times better; at
// 1024² a chain set is 25 million values).
function packU8(data, n, cw, out, w, k, src, { min, max }) {
  for (let t = 0; t < n; t++) out[t * w + k] = encodeUnorm8(data[t * cw + src], min, max);
}

function packHalf(bits, n, cw, out, w, k, src) {
  // exact: the chain holds binary16 values already
  for (let t = 0; t < n; t++) out[t * w + k] = halfBitsOfFloat32Bits(bits[t * cw + src]);
}

function packFloat(data, n, cw, out, w, k, src) {
  for (let t = 0; t < n; t++) out[t * w + k] = data[t * cw + src];
}

function packLevel({ size, data }, chain, sources, ranges) {
  const n = size * size;
  const w = sources.length;
  const cw = chain.components;
  // float32 in the chain's own order (every component a source, in turn): its array as it is
  if (chain.precision === 'f32' && w === cw && sources.every((src, k) => src === k)) return { data, width: size, height: size };
  const out = chain.precision === 'u8' ? new Uint8Array(n * w)
    : chain.precision === 'f16' ? new Uint16Array(n * w) : new Float32Array(n * w);
  const bits = new Uint32Array(data.buffer, data.byteOffset, data.length);
  for (let k = 0; k < w; k++) {
    const src = sources[k];
    if (typeof src !== 'number') {
      const padded = chain.precision === 'u8' ? encodeUnorm8(src.pad, 0, 1) : chain.precision === 'f16' ? halfBits(src.pad) : src.pad;
      for (let t = 0; t < n; t++) out[t * w + k] = padded;
    } else if (chain.precision === 'u8') packU8(data, n, cw, out, w, k, src, ranges[k]);
    else if (chain.precision === 'f16') packHalf(bits, n, cw, out, w, k, src);
    else packFloat(data, n, cw, out, w, k, src);
  }
  return { data: out, width: size, height: size };
}

/**
 * uploadLevels(chain) → [{ format, type, ranges: [{ min, max }], names, mipmaps }] per texture.
 * Values round-trip exactly: the chain already holds quantized values.
 */
export function uploadLevels(chain) {
  return chain.textures.map(({ format, sources }) => {
    const ranges = sources.map((s) => (typeof s === 'number' ? chain.layout[s] : { min: 0, max: 1 }));
    return {
      format,
      type: chain.precision,
      ranges: ranges.map(({ min, max }) => ({ min, max })),
      names: sources.map((s) => (typeof s === 'number' ? chain.layout[s].name : 'pad')),
      mipmaps: chain.levels.map((level) => packLevel(level, chain, sources, ranges)),
    };
  });
}
