// The shimmer meter: how much a picture's brightness changes per pixel when the camera moves by
// less than a pixel (specular aliasing shows as highlights "popping in and out of existence":
// Hill, "Specular Showdown in the Wild West", 2011). Pictures are RGBA float arrays: linear radiance,
// alpha < 0 where there is no surface. Brightness is the Rec. 709 luminance of the tone-mapped
// colour (ITU-R BT.709 weights 0.2126, 0.7152, 0.0722), as displayed.
import { toneMap } from './bandedRmse.js';

function brightness(image, o) {
  return 0.2126 * toneMap(image[o]) + 0.7152 * toneMap(image[o + 1]) + 0.0722 * toneMap(image[o + 2]);
}

/** Mean |Δ brightness| over pixels that are surface in both pictures; NaN if there are none. */
export function meanBrightnessChange(a, b) {
  if (a.length !== b.length || a.length % 4) throw new RangeError('images must be RGBA of equal size');
  let sum = 0;
  let count = 0;
  for (let o = 0; o < a.length; o += 4) {
    if (!(a[o + 3] >= 0 && b[o + 3] >= 0)) continue;
    sum += Math.abs(brightness(a, o) - brightness(b, o));
    count += 1;
  }
  return count ? sum / count : NaN;
}
