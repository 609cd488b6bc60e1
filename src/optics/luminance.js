/**
 * Relative luminance of linear Rec. 709 RGB (ITU-R BT.709-6, Item 3.3 weights).
 * @param {ArrayLike<number>} rgb
 */
export function luminance(rgb) {
  const [r, g, b] = [rgb[0], rgb[1], rgb[2]];
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}
