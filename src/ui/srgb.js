// sRGB ↔ linear RGB by the sRGB transfer function of IEC 61966-2-1:1999 (the piecewise curve, not
// a 2.2 power): colour pickers and CSS speak sRGB, shaders light in linear RGB.

/** One sRGB-encoded channel in [0, 1] to linear. */
export function srgbToLinear(c) {
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

/** One linear channel in [0, 1] to sRGB-encoded. */
export function linearToSrgb(c) {
  return c <= 0.0031308 ? c * 12.92 : 1.055 * c ** (1 / 2.4) - 0.055;
}

/** '#rrggbb' (sRGB, as a colour control gives it) to linear [r, g, b]. */
export function hexToLinear(hex) {
  const match = /^#?([0-9a-f]{6})$/i.exec(String(hex));
  if (!match) throw new RangeError(`A colour must be #rrggbb, not ${String(hex).slice(0, 20)}.`);
  const value = parseInt(match[1], 16);
  return [value >> 16, (value >> 8) & 255, value & 255].map((byte) => srgbToLinear(byte / 255));
}

/** Linear [r, g, b] (clamped to [0, 1]) to '#rrggbb' in sRGB, for a CSS swatch. */
export function linearToHex(rgb) {
  const byte = (c) => Math.round(linearToSrgb(Math.min(1, Math.max(0, c))) * 255).toString(16).padStart(2, '0');
  return `#${rgb.map(byte).join('')}`;
}
