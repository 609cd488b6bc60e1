// Image error of a shaded picture against its ground truth, overall and per mip-level band.
// Both images are RGBA float arrays as read back from the panel's render targets: linear
// radiance in RGB and, in alpha, the mip level λ the pixel uses (negative where there is no
// surface, e.g. sky). Errors are taken after the display tone map, so they measure what is seen.

/** The display tone map 1 − e^(−x) per channel (GLSL twin: toneMap in src/panels/normal-mips/normal-mips.frag.glsl). */
export function toneMap(x) {
  return 1 - Math.exp(-Math.max(x, 0));
}

/**
 * bandedRmse(image, truth, { bands }) → { rmse, count, bands: [{ level, rmse, count }] }.
 * RMSE over the R, G, B channels of tone-mapped values, over pixels whose alpha (the λ of
 * `image`) is ≥ 0; band k holds the pixels with floor(λ) = k (the last band takes all λ ≥ bands − 1).
 * A band with no pixels has rmse NaN.
 */
export function bandedRmse(image, truth, { bands = 1 } = {}) {
  if (image.length !== truth.length || image.length % 4) throw new RangeError('images must be RGBA of equal size');
  if (!Number.isInteger(bands) || bands < 1) throw new RangeError(`bands must be an integer >= 1, got ${bands}`);
  const sums = new Float64Array(bands);
  const counts = new Uint32Array(bands);
  for (let o = 0; o < image.length; o += 4) {
    const lod = image[o + 3];
    if (!(lod >= 0)) continue;
    let e = 0;
    for (let c = 0; c < 3; c++) {
      const d = toneMap(image[o + c]) - toneMap(truth[o + c]);
      e += d * d;
    }
    const k = Math.min(bands - 1, Math.floor(lod));
    sums[k] += e;
    counts[k] += 1;
  }
  let total = 0;
  let count = 0;
  const perBand = [];
  for (let k = 0; k < bands; k++) {
    total += sums[k];
    count += counts[k];
    perBand.push({ level: k, rmse: counts[k] ? Math.sqrt(sums[k] / (3 * counts[k])) : NaN, count: counts[k] });
  }
  return { rmse: count ? Math.sqrt(total / (3 * count)) : NaN, count, bands: perBand };
}
