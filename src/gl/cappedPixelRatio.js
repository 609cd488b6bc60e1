// The drawing buffer's pixel ratio: the device's, capped so that a 4K projector or a retina laptop
// stays fast (a software renderer or a weak integrated GPU pays per pixel).

/** Device pixel ratio capped at maxRatio and so that the drawing buffer holds at most maxPixels. */
export function cappedPixelRatio(cssWidth, cssHeight, deviceRatio, maxRatio = 2, maxPixels = 3_000_000) {
  const area = Math.max(1, cssWidth * cssHeight);
  return Math.max(0.5, Math.min(deviceRatio || 1, maxRatio, Math.sqrt(maxPixels / area)));
}
