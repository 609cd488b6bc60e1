// Half an 8-bit sRGB step as a change of a linear value: the strictest display budget, with the sRGB
// transfer function it is measured through. A module of its own so that a panel's schema can take
// its default tolerance from it without the advisor (advisor.js says why half a step).

/** 8-bit codes of half a step: the display's own rounding, the strictest budget. */
export const HALF_STEP_CODES = 0.5;

/**
 * sRGB transfer function, linear → encoded (IEC 61966-2-1:1999).
 * @param {number} x
 */
export function srgbEncode(x) {
  return x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055;
}

/**
 * Its inverse, encoded → linear.
 * @param {number} v
 */
export function srgbDecode(v) {
  return v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
}

/**
 * The smallest change of a linear value `level` in [0, 1] that moves its sRGB encoding by half an
 * 8-bit step (the nearer of the step up and the step down). level 1 (default): 0.0044548;
 * level 0: 1.5176e-4.
 */
export function invisibleThreshold(level = 1) {
  const half = HALF_STEP_CODES / 255;
  const e = srgbEncode(level);
  const down = e - half >= 0 ? level - srgbDecode(e - half) : Infinity;
  const up = e + half <= 1 ? srgbDecode(e + half) - level : Infinity;
  return Math.min(down, up);
}
