// Error heatmap: piecewise-linear through five stops of matplotlib's "inferno" (van der Walt &
// Smith, CC0), in sRGB. Twin of src/ui/colormap.js, which draws the legend with the same stops.
vec3 colormap(float t) {
  const vec3 c0 = vec3(0.000, 0.000, 0.016);
  const vec3 c1 = vec3(0.341, 0.063, 0.431);
  const vec3 c2 = vec3(0.737, 0.216, 0.329);
  const vec3 c3 = vec3(0.976, 0.557, 0.035);
  const vec3 c4 = vec3(0.988, 1.000, 0.643);
  float x = clamp(t, 0.0, 1.0) * 4.0;
  if (x < 1.0) return mix(c0, c1, x);
  if (x < 2.0) return mix(c1, c2, x - 1.0);
  if (x < 3.0) return mix(c2, c3, x - 2.0);
  return mix(c3, c4, x - 3.0);
}
