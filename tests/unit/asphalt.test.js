import { describe, expect, it } from 'vitest';
import { fresnelExact, normalIncidence } from '../../src/optics/fresnel.js';
import {
  SCENE, cameraBasis, highlightInView, pixelRay, shadeRoad, sunDirection,
} from '../../src/panels/asphalt/model.js';

const DEG = Math.PI / 180;
const base = { camEl: 6, sunEl: 10, roughness: 0.8, nT: 1.55, fresnel: true };
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

describe('camera and sun', () => {
  it('the centre ray is the camera forward, pitched down by the elevation, with the sun ahead', () => {
    const ray = pixelRay(30, 0, 0, 2);
    expect(Math.asin(-ray[1]) / DEG).toBeCloseTo(30, 12);
    expect(ray[2]).toBeGreaterThan(0);
    expect(sunDirection(10)[2]).toBeGreaterThan(0);
    const { forward, up, right } = cameraBasis(37);
    expect(dot(forward, up)).toBeCloseTo(0, 15);
    expect(dot(forward, right)).toBeCloseTo(0, 15);
  });
  it('the top edge of the view is half the field of view above the centre', () => {
    const top = pixelRay(90, 0, 1, 1.5);
    expect(Math.acos(-top[1]) / DEG).toBeCloseTo(SCENE.fovY / 2, 10);
  });
});

describe('road shading', () => {
  it('F is fresnelExact at the angle between the sun and the half-vector, or R0 with Fresnel off', () => {
    const dir = pixelRay(6, 0.2, -0.3, 2);
    const hit = shadeRoad(dir, base);
    const l = sunDirection(10);
    const v = dir.map((x) => -x);
    const h = l.map((x, i) => x + v[i]);
    const cosD = dot(l, h) / Math.hypot(...h);
    expect(hit.thetaD).toBeCloseTo(Math.acos(cosD) / DEG, 10);
    expect(hit.F).toBeCloseTo(fresnelExact(cosD, 1, 1.55), 15);
    expect(shadeRoad(dir, { ...base, fresnel: false }).F).toBe(normalIncidence(1, 1.55));
  });
  it('the sky is not road', () => {
    expect(shadeRoad(pixelRay(2, 0, 0.9, 2), base)).toBeNull();
  });
  it('overhead there is no visible highlight: the specular part stays below the diffuse road', () => {
    const { peak, centre } = highlightInView({ ...base, camEl: 90 }, 2);
    expect(peak.specular).toBeLessThan(peak.diffuse);
    expect(centre.F).toBeLessThan(0.06);
  });
  it('near grazing the highlight sits at the mirror point and outshines the road many times', () => {
    const { peak } = highlightInView({ ...base, camEl: 4 }, 2, 801);
    expect(peak.thetaD).toBeCloseTo(90 - base.sunEl / 2, 0); // mirror point: h = n, θd = 90° − sunEl
    expect(peak.F).toBeGreaterThan(0.5);
    expect(peak.specular / peak.diffuse).toBeGreaterThan(20);
  });
  it('Fresnel off leaves the grazing highlight at R0/F of its strength', () => {
    const on = highlightInView({ ...base, camEl: 4 }, 2).peak;
    const off = highlightInView({ ...base, camEl: 4, fresnel: false }, 2).peak;
    expect(off.specular / on.specular).toBeCloseTo(normalIncidence(1, 1.55) / on.F, 10);
    expect(off.specular).toBeLessThan(on.specular / 10);
  });
});
