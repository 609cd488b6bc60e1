// Storage precisions of a mip level, as the value the shader reads back:
//   u8   8-bit unorm: code c = round(255·(x − min)/(max − min)), read as min + (max − min)·c/255
//        (normals: c = n/2 + ½). Flat (0, 0, 1) becomes (1/255, 1/255, 1): 0 sits
//        between codes 127 and 128, and Math.round takes 128, as a baker's round(255·c) does.
//   f16  IEEE binary16, round to nearest even (@petamoriken/float16 f16round; RGBA16F / HalfFloatType)
//   f32  IEEE binary32 (Math.fround; RGBA32F / FloatType, which needs OES_texture_float_linear
//        to be filtered; the panel says so where it is missing)
// The decoded value is rounded to float32 at the end: the shader computes in 32-bit floats.
import { f16round } from '@petamoriken/float16';
import { roundHalfArray } from './float16Bits.js';

export const PRECISIONS = Object.freeze({
  u8: Object.freeze({ bytes: 1, label: '8-bit unorm' }),
  f16: Object.freeze({ bytes: 2, label: '16-bit float' }),
  f32: Object.freeze({ bytes: 4, label: '32-bit float' }),
});

export function checkPrecision(precision) {
  if (!Object.hasOwn(PRECISIONS, precision)) {
    throw new RangeError(`precision must be one of ${Object.keys(PRECISIONS).join(', ')}, got ${String(precision)}`);
  }
  return precision;
}

/** The 8-bit code of x in [min, max] (clamped). */
export function encodeUnorm8(x, min, max) {
  const t = (x - min) * (255 / (max - min));
  return Math.round(t < 0 ? 0 : t > 255 ? 255 : t);
}

export function decodeUnorm8(code, min, max) {
  return Math.fround(min + ((max - min) * code) / 255);
}

/** quantize(x, precision, min, max): the value the shader reads after storing x. */
export function quantize(x, precision, min = -1, max = 1) {
  switch (precision) {
    case 'u8':
      return decodeUnorm8(encodeUnorm8(x, min, max), min, max);
    case 'f16':
      return f16round(x);
    case 'f32':
      return Math.fround(x);
    default:
      return checkPrecision(precision);
  }
}

/**
 * Quantizes an interleaved Float32Array in place, channel by channel: data holds texels of
 * layout.length values, channel k with range [layout[k].min, layout[k].max]. Same results as
 * quantize() per element (the inputs are float32 already), inlined for whole chains.
 */
export function quantizeInPlace(data, layout, precision) {
  checkPrecision(precision);
  if (!(data instanceof Float32Array)) throw new TypeError('quantizeInPlace expects a Float32Array');
  if (precision === 'f32') return data;
  if (precision === 'f16') return roundHalfArray(data);
  const w = layout.length;
  const decoded = new Float32Array(256);
  for (let k = 0; k < w; k++) {
    const { min, max } = layout[k];
    const scale = 255 / (max - min); // the same expressions as encodeUnorm8, inlined
    for (let c = 0; c < 256; c++) decoded[c] = decodeUnorm8(c, min, max);
    for (let o = k; o < data.length; o += w) {
      const t = (data[o] - min) * scale;
      data[o] = decoded[Math.round(t < 0 ? 0 : t > 255 ? 255 : t)];
    }
  }
  return data;
}
