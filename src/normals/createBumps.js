// Bumps: a frequency × frequency grid of spherical caps on a flat ground, one per cell.
// A cap is the top of a sphere of radius R = b / sin θm over a disk of radius b, so its normal
// n = (x, y, √(R² − r²)) / R tilts from 0 at the centre to θm at the rim. θm = 90° would be a
// true hemisphere, but its slope second moment ∫ r²/(R² − r²) dA diverges (log) at the rim, which
// LEAN/CLEAN cannot store; θm is therefore capped at 85° (slope 11.4) and defaults to 45°, so
// slopes stay below about 1 (z > 0.7) unless an extreme map is asked for.
import { checkFrequency, checkRange, degToRad, fract, makeMap } from './mapMath.js';

function capGeometry({ frequency, edgeAngleDeg, fill }) {
  const theta = degToRad(edgeAngleDeg);
  const b = (fill * 0.5) / frequency; // base radius in tile units
  const R = b / Math.sin(theta);
  return { theta, b, R };
}

function checkParams({ frequency = 8, edgeAngleDeg = 45, fill = 0.8 } = {}) {
  checkFrequency(frequency);
  checkRange(edgeAngleDeg, 1, 85, 'edgeAngleDeg');
  checkRange(fill, 0.05, 1, 'fill');
  return { frequency, edgeAngleDeg, fill };
}

/**
 * createBumps({ frequency = 8, edgeAngleDeg = 45, fill = 0.8 }): fill is the cap diameter over
 * the cell side. Slope inside the cap: b = −∇h = (x, y) / √(R² − r²), (x, y) from the cell centre.
 */
export function createBumps(options) {
  const params = checkParams(options);
  const { b, R } = capGeometry(params);
  const f = params.frequency;
  const b2 = b * b;
  const R2 = R * R;
  return makeMap('bumps', params, (u, v, out = [0, 0]) => {
    const x = (fract(u * f) - 0.5) / f;
    const y = (fract(v * f) - 0.5) / f;
    const r2 = x * x + y * y;
    if (r2 >= b2) {
      out[0] = 0;
      out[1] = 0;
    } else {
      const w = 1 / Math.sqrt(R2 - r2);
      out[0] = x * w;
      out[1] = y * w;
    }
    return out;
  });
}

/**
 * Exact averages over one whole cell (the ground truth of every mip texel that covers whole
 * cells), by integrating the cap in polar coordinates:
 *   ∫cap n_z dA = ∫0^b √(R² − r²)/R · 2πr dr = (2πR²/3)(1 − cos³θm),
 *   ∫cap |b|² dA = ∫0^b r²/(R² − r²) · 2πr dr = π(R² ln(1/cos²θm) − b²)   (w = R² − r²).
 * By symmetry the mean n_x, n_y, b_x, b_y and M_xy are 0 and M_xx = M_yy = |b|²/2.
 * Returns { nz, slopeVariance } with slopeVariance = E[b_x² + b_y²] (CLEAN's M; Baker, GDC 2011).
 */
export function bumpCellMean(options) {
  const params = checkParams(options);
  const { theta, b, R } = capGeometry(params);
  const area = 1 / (params.frequency * params.frequency);
  const c = Math.cos(theta);
  const capNz = ((2 * Math.PI * R * R) / 3) * (1 - c * c * c);
  const nz = (area - Math.PI * b * b + capNz) / area;
  const slopeVariance = (Math.PI * (R * R * Math.log(1 / (c * c)) - b * b)) / area;
  return { nz, slopeVariance };
}
