// How much larger a real GPU's rounding errors are than the JS emulation's, where the emulation
// rounds every operation exactly to float32 or float16 (rounding.js) and a GPU's division, square
// root and powers are not correctly rounded. Measured for the exact methods (exact c/g in both
// orders, exact s/p, exact conductor), whose errors are rounding alone, by the speed-accuracy
// panel's benchmark on an NVIDIA H200 through Chromium 156 and ANGLE on Vulkan, 2026-12-04
// (bench/gpu/results-h200-2026-12-04.json; tests/unit/emulationGap.test.js recomputes the ranges).
// The lowest and highest ratio of read-back to emulated largest error, to one decimal.
export const EMULATION_GAP = Object.freeze({
  device: 'NVIDIA H200',
  date: '2026-12-04',
  highp: Object.freeze([1.2, 1.5]),
  mediump: Object.freeze([1.3, 1.6]),
});
