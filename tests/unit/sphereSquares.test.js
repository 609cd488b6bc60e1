// The squares the hero redraws when only its optics change (trioCamera.js sphereSquares): every
// pixel outside them must be sky in spheres.frag.glsl, anti-aliased rim included, and each square
// must lie in the view that owns its pixels. The shader's per-pixel ray is recomputed here.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { sphereSquares, trioCamera, VIEW_COUNT } from '../../src/panels/spheres/trioCamera.js';

/** d (the ray's distance from the sphere's centre) at the centre of pixel (x, y), as spheres.frag.glsl. */
function rayDistance(camera, width, height, count, x, y) {
  const viewWidth = width / count;
  const slot = Math.min(count - 1, Math.floor((x + 0.5) / viewWidth));
  const nx = ((x + 0.5 - slot * viewWidth) / viewWidth) * 2 - 1;
  const ny = ((y + 0.5) / height) * 2 - 1;
  const sx = nx * camera.tanHalfFov * (viewWidth / height);
  const sy = ny * camera.tanHalfFov;
  const dir = [0, 1, 2].map((i) => camera.forward[i] + sx * camera.right[i] + sy * camera.up[i]);
  const length = Math.hypot(...dir);
  const b = dir.reduce((sum, v, i) => sum + (camera.eye[i] * v) / length, 0);
  const eye2 = camera.eye.reduce((sum, v) => sum + v * v, 0);
  return { d: Math.sqrt(Math.max(eye2 - b * b, 0)), slot };
}

const inside = (squares, x, y) => squares.some(([sx, sy, w, h]) => x >= sx && x < sx + w && y >= sy && y < sy + h);

describe('sphereSquares', () => {
  it('leaves out only sky: outside every square the ray misses the sphere by more than the rim', () => {
    fc.assert(fc.property(
      fc.record({
        azimuth: fc.double({ min: -180, max: 180, noNaN: true }),
        elevation: fc.double({ min: -85, max: 85, noNaN: true }),
        distance: fc.double({ min: 2.2, max: 10, noNaN: true }),
      }),
      fc.integer({ min: 30, max: 240 }), fc.integer({ min: 20, max: 120 }), fc.constantFrom(1, VIEW_COUNT),
      (view, width, height, count) => {
        const camera = trioCamera(view);
        const squares = sphereSquares({ distance: view.distance, tanHalfFov: camera.tanHalfFov }, width, height, count);
        for (let y = 0; y < height; y += 1) {
          for (let x = 0; x < width; x += 1) {
            if (inside(squares, x, y)) continue;
            const { d } = rayDistance(camera, width, height, count, x, y);
            // coverage = 0.5 + (1 − d) / fwidth(d) is 0 once d − 1 ≥ fwidth/2; fwidth over a 2×2
            // block is at most about twice d's change per pixel, which is below 0.5·(d − 1) here.
            const step = Math.max(
              Math.abs(rayDistance(camera, width, height, count, x + 1, y).d - d),
              Math.abs(rayDistance(camera, width, height, count, x, y + 1).d - d),
            );
            if (d - 1 < 2 * step) return false;
          }
        }
        return true;
      },
    ), { numRuns: 40 });
  });

  it('puts each square inside the view that owns its pixels', () => {
    for (const [width, count] of [[900, 3], [901, 3], [1001, 3], [640, 1]]) {
      for (const distance of [2.2, 3, 6, 10]) {
        const camera = trioCamera({ azimuth: 0, elevation: 15, distance });
        const squares = sphereSquares({ distance, tanHalfFov: camera.tanHalfFov }, width, 300, count);
        expect(squares).toHaveLength(count);
        squares.forEach(([x, y, w, h], slot) => {
          expect(y).toBeGreaterThanOrEqual(0);
          expect(y + h).toBeLessThanOrEqual(300);
          for (const px of [x, x + w - 1]) expect(rayDistance(camera, width, 300, count, px, 150).slot).toBe(slot);
        });
      }
    }
  });

  it('is a small part of the picture at the default distance (what a change of n redraws)', () => {
    const camera = trioCamera({ azimuth: 0, elevation: 15, distance: 6 });
    const area = sphereSquares({ distance: 6, tanHalfFov: camera.tanHalfFov }, 900, 300, VIEW_COUNT)
      .reduce((sum, [, , w, h]) => sum + w * h, 0);
    expect(area / (900 * 300)).toBeGreaterThan(0.3);
    expect(area / (900 * 300)).toBeLessThan(0.55);
  });
});
