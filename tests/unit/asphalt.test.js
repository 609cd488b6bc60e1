import { describe, expect, it } from 'vitest';
import { fresnelExact, normalIncidence } from '../../src/optics/fresnel.js';
import {
  SCENE, cameraBasis, highlightInView, pixelRay, shadeRoad, sheenGrowth, sightBelow, specularAlbedo, sunDirection,
} from '../../src/panels/asphalt/physics.js';
import { questionById } from '../../src/homework/questions.js';
import { specularAlbedoByDirections } from './oracle/roadOracle.js';

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
  it('near grazing the highlight sits at the horizon and outshines the road many times', () => {
    const { peak } = highlightInView({ ...base, camEl: 4 }, 2, 801);
    // Not at the mirror point (h = n, θd = 90° − sunEl = 80°): the lobe's 1/cosθv carries the peak to
    // the far road, where v runs along it and l·v = −cos(sunEl), so θd = (180° − sunEl)/2.
    expect(Math.abs(peak.thetaD - 80)).toBeGreaterThan(4);
    expect(peak.thetaD).toBeCloseTo((180 - base.sunEl) / 2, 1);
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

describe('how much the road reflects, and why it shines', () => {
  it('the specular albedo holds its shown digits against a far finer grid, and a direct integral agrees', () => {
    for (const roughness of [0.2, 0.45, 1]) {
      for (const sunEl of [2, 10, 45]) {
        const v = { ...base, roughness, sunEl };
        expect(Math.abs(specularAlbedo(v) - specularAlbedo(v, 400)), `${roughness} ${sunEl}`).toBeLessThan(2.5e-4);
      }
    }
    expect(specularAlbedo({ ...base, sunEl: 10 })).toBeCloseTo(specularAlbedoByDirections({ ...base, sunEl: 10 }, 600), 3);
    expect(specularAlbedo({ ...base, sunEl: 60 })).toBeCloseTo(specularAlbedoByDirections({ ...base, sunEl: 60 }, 300), 4);
  });
  it('at the default roughness only a few per cent is reflected specularly, even at 80–85°', () => {
    // Issue figures: about 2.7 % head-on, 4.1 % at 60°, 7.3 % at 80°, 9.1 % at 85° (θ from the normal).
    const at = (theta) => specularAlbedo({ ...base, sunEl: 90 - theta });
    expect(at(0)).toBeCloseTo(0.0265, 3);
    expect(at(60)).toBeCloseTo(0.0406, 3);
    expect(at(80)).toBeCloseTo(0.0734, 3);
    expect(at(85)).toBeCloseTo(0.0914, 3);
    expect(Math.abs(at(85) - SCENE.albedo)).toBeLessThan(0.005); // about the diffuse albedo
    // Fresnel off: F = R0 everywhere, so less is reflected at grazing.
    expect(specularAlbedo({ ...base, sunEl: 10, fresnel: false })).toBeLessThan(at(80) / 1.8);
  });
  it('the growth against the road straight below is the lobe times F, and both factors are large', () => {
    const g = sheenGrowth({ ...base, camEl: 6 }, 2);
    const now = highlightInView({ ...base, camEl: 6 }, 2).peak;
    const straightDown = shadeRoad([0, -1, 0], base);
    expect(g.total).toBeCloseTo(now.specular / straightDown.specular, 10);
    expect(now.below).toBeLessThan(1e-6); // at the default view the brightest spot is at the horizon
    expect(g.lobe).toBeGreaterThan(18);
    expect(g.lobe).toBeLessThan(19);
    expect(g.fresnel).toBeGreaterThan(11);
    // The same two directions from any camera that sees them: the field of view drops out.
    const fromHigher = sheenGrowth({ ...base, camEl: 15 }, 2);
    expect(fromHigher.spot.below).toBeLessThan(1e-6);
    expect(fromHigher.total).toBeCloseTo(g.total, 6);
    // With Fresnel off the lobe grows just the same and F not at all.
    const off = sheenGrowth({ ...base, camEl: 6, fresnel: false }, 2);
    expect(off.lobe).toBeCloseTo(g.lobe, 10);
    expect(off.fresnel).toBe(1);
  });
  it('the brightest spot is refined off the grid: no row of a finer scan is brighter', () => {
    for (const camEl of [30, 60, 75]) {
      const { peak } = highlightInView({ ...base, camEl }, 2);
      const fine = highlightInView({ ...base, camEl }, 2, 4001).column;
      for (const row of fine) expect(row.specular).toBeLessThanOrEqual(peak.specular * (1 + 1e-12));
    }
  });
});

describe('the homework question asks what the panel computes', () => {
  const q = questionById('asphalt-outshine');
  it('its answer is the direction below the horizon where a sun-ward spot\'s specular equals its diffuse part', () => {
    for (const nT of [1.5, 1.55, 1.6]) {
      for (const sunEl of [10, 15, 20]) {
        const below = q.expected({ nT, sunEl });
        const values = { sunEl, roughness: 0.8, nT, fresnel: true };
        const spot = (b) => shadeRoad(sightBelow(b), values);
        expect(spot(below).specular / spot(below).diffuse).toBeCloseTo(1, 8);
        expect(spot(below).below).toBeCloseTo(below, 9); // what the hover readout shows
        // Diffuse wins looking steeper, specular looking lower.
        expect(spot(below + 2).specular).toBeLessThan(spot(below + 2).diffuse);
        expect(spot(below - 2).specular).toBeGreaterThan(spot(below - 2).diffuse);
      }
    }
  });
  it('does not depend on the camera: the panel\'s own pixel at that direction, from any camera, gives the same', () => {
    const values = { sunEl: 10, roughness: 0.8, nT: 1.55, fresnel: true };
    const below = q.expected(values);
    for (const camEl of [below - 15, below, below + 15]) {
      // The central column's pixel that looks `below` under the horizon, from a camera at camEl.
      const ndcY = Math.tan((camEl - below) * DEG) / Math.tan((SCENE.fovY / 2) * DEG);
      const hit = shadeRoad(pixelRay(camEl, 0, ndcY, 16 / 9), { ...values, camEl });
      expect(hit.below).toBeCloseTo(below, 9);
      expect(hit.specular / hit.diffuse).toBeCloseTo(1, 8);
    }
  });
  it('its start state is the panel overhead with the question\'s sun and index', () => {
    expect(q.state({ nT: 1.55, sunEl: 15 })).toEqual({ nT: 1.55, sunEl: 15, roughness: 0.8, camEl: 90, fresnel: true });
  });
});
