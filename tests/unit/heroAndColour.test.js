// The hero's analytic camera (its JS readout and its shader cast the same ray), the sRGB transfer
// function that replaced three.js's Color, and the uniform conversion of the plain WebGL2 view.
import { describe, expect, it } from 'vitest';
import { Color } from 'three';
import { hitSphere, rayThrough, trioCamera, FOV_DEG } from '../../src/panels/spheres/trioCamera.js';
import { hexToLinear, linearToHex, linearToSrgb, srgbToLinear } from '../../src/ui/srgb.js';
import { uniformFloats } from '../../src/gl/createProgram.js';
import { DEG } from '../../src/optics/angles.js';

describe('trioCamera', () => {
  it('looks at the sphere centre: the middle of a view sees θ = 0', () => {
    for (const view of [{ azimuth: 0, elevation: 12, distance: 6 }, { azimuth: -140, elevation: 70, distance: 2.2 }]) {
      const camera = trioCamera(view);
      const hit = hitSphere(camera.eye, rayThrough(camera, 0, 0, 1.2));
      expect(hit.cosTheta).toBeCloseTo(1, 12);
      expect(Math.hypot(...hit.normal)).toBeCloseTo(1, 12);
    }
  });

  it('meets the silhouette where the ray is tangent: sin α = 1/d, cos θ → 0', () => {
    const view = { azimuth: 20, elevation: 0, distance: 6 };
    const camera = trioCamera(view);
    const alpha = Math.asin(1 / view.distance); // angle between the axis and a tangent ray
    const y = Math.tan(alpha) / Math.tan((FOV_DEG / 2) * DEG);
    expect(hitSphere(camera.eye, rayThrough(camera, 0, y * (1 - 1e-9), 1)).cosTheta).toBeLessThan(1e-3);
    expect(hitSphere(camera.eye, rayThrough(camera, 0, y * (1 + 1e-6), 1))).toBeNull();
  });

  it('has an orthonormal basis with up toward +y (as three.js lookAt)', () => {
    const { forward, right, up } = trioCamera({ azimuth: 35, elevation: 40, distance: 5 });
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    expect(dot(forward, right)).toBeCloseTo(0, 12);
    expect(dot(forward, up)).toBeCloseTo(0, 12);
    expect(dot(right, up)).toBeCloseTo(0, 12);
    expect(up[1]).toBeGreaterThan(0);
    expect(right[1]).toBeCloseTo(0, 12);
  });
});

describe('sRGB transfer function (IEC 61966-2-1)', () => {
  it('agrees with three.js Color for every byte, both ways', () => {
    for (let byte = 0; byte < 256; byte += 1) {
      const hex = `#${byte.toString(16).padStart(2, '0').repeat(3)}`;
      const ours = hexToLinear(hex);
      const theirs = new Color(hex);
      expect(ours[0]).toBeCloseTo(theirs.r, 9); // three.js rounds 1/12.92 to 0.0773993808
      expect(linearToHex(ours)).toBe(hex);
      expect(linearToHex([theirs.r, theirs.g, theirs.b])).toBe(`#${theirs.getHexString()}`);
    }
  });

  it('is continuous at its breakpoints and inverts itself', () => {
    expect(srgbToLinear(0.04045)).toBeCloseTo(0.04045 / 12.92, 12);
    for (const c of [0, 0.001, 0.2, 0.5, 1]) expect(linearToSrgb(srgbToLinear(c))).toBeCloseTo(c, 12);
  });

  it('rejects what is not #rrggbb', () => {
    expect(() => hexToLinear('red')).toThrow(RangeError);
  });
});

describe('uniformFloats', () => {
  it('takes numbers, booleans, arrays and vectors', () => {
    expect(uniformFloats(2, 1)).toEqual([2]);
    expect(uniformFloats(true, 1)).toEqual([1]);
    expect(uniformFloats([1, 2, 3], 3)).toEqual([1, 2, 3]);
    expect(uniformFloats({ x: 1, y: 2, z: 3 }, 3)).toEqual([1, 2, 3]);
    expect(uniformFloats({ r: 0.1, g: 0.2, b: 0.3 }, 3)).toEqual([0.1, 0.2, 0.3]);
    expect(() => uniformFloats('x', 1)).toThrow(TypeError);
  });
});
