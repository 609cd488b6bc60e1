// JS twin of shaders/colormap.glsl: five sRGB stops of matplotlib's "inferno" (CC0).
export const COLORMAP_STOPS = [
  [0.0, 0.0, 0.016],
  [0.341, 0.063, 0.431],
  [0.737, 0.216, 0.329],
  [0.976, 0.557, 0.035],
  [0.988, 1.0, 0.643],
];

/** sRGB colour in [0, 1]³ for t in [0, 1] (clamped), as the shader computes it. */
export function colormap(t) {
  const x = Math.min(1, Math.max(0, t)) * 4;
  const i = Math.min(3, Math.floor(x));
  const f = x - i;
  const a = COLORMAP_STOPS[i];
  const b = COLORMAP_STOPS[i + 1];
  return a.map((v, j) => v + (b[j] - v) * f);
}

/** A CSS linear-gradient drawing the colormap from left (0) to right (1). */
export function colormapGradient(direction = 'to right') {
  const stops = COLORMAP_STOPS.map((c, i) => {
    const [r, g, b] = c.map((v) => Math.round(v * 255));
    return `rgb(${r} ${g} ${b}) ${i * 25}%`;
  });
  return `linear-gradient(${direction}, ${stops.join(', ')})`;
}
