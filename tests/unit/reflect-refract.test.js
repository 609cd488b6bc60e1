import { describe, expect, it } from 'vitest';
import { centreRay, reflectionBand, splitByElevation, REFLECTION_BANDS } from '../../src/panels/reflect-refract/physics.js';
import { bandLabel } from '../../src/panels/reflect-refract/words.js';
import { absError, cosOfDegrees, dielectricR } from './oracle/fresnelOracle.js';
import { usePseudoLocale, wordsOutside } from './inPseudoLocale.js';

const DEG = Math.PI / 180;

describe('the centre ray', () => {
  it('at 10° elevation (80° from the normal) on water reflects 0.3479', () => {
    const ray = centreRay(10, 1.333);
    expect(ray.thetaDeg).toBeCloseTo(80, 12);
    expect(absError(ray.R, dielectricR(cosOfDegrees(80), 1, 1.333))).toBeLessThan(1e-12); // the 50-digit oracle: 0.347916706959…
    expect(ray.R).toBeCloseTo(0.3479, 4);
    expect(ray.R + ray.T).toBe(1);
    expect(ray.band.id).toBe('some');
  });
  it('looking straight down reflects R0 and refracts undeviated', () => {
    const ray = centreRay(90, 1.333);
    expect(ray.R).toBeCloseTo(((1.333 - 1) / (1.333 + 1)) ** 2, 15);
    expect(ray.thetaTDeg).toBeCloseTo(0, 12);
    expect(ray.band.id).toBe('none');
    expect(centreRay(90, 1.5).R).toBeCloseTo(0.04, 15);
  });
  it('obeys Snell: sin θt = sin θ / n', () => {
    for (const e of [2, 10, 30, 60]) {
      const ray = centreRay(e, 1.5);
      expect(Math.sin(ray.thetaTDeg * DEG)).toBeCloseTo(Math.sin(ray.thetaDeg * DEG) / 1.5, 14);
    }
    // Near grazing the refracted ray approaches the critical angle of water, 48.6°.
    expect(centreRay(0.001, 1.333).thetaTDeg).toBeCloseTo(48.6, 1);
  });
  it('sweeps from little reflection to lots as the view lowers', () => {
    expect(bandLabel(centreRay(60, 1.333).band)).toBe('little reflection');
    expect(bandLabel(centreRay(20, 1.333).band)).toBe('some reflection');
    expect(bandLabel(centreRay(2, 1.333).band)).toBe('lots of reflection');
  });
});

describe('bands and the CSV table', () => {
  it('bands cover [0, 1] in order', () => {
    expect(reflectionBand(0).id).toBe('nothing'); // n_t = 1: no interface, no reflection at all
    expect(bandLabel(reflectionBand(0))).toBe('no reflection');
    expect(reflectionBand(1e-9).id).toBe('none');
    expect(reflectionBand(0.0999).id).toBe('none');
    expect(reflectionBand(0.1).id).toBe('some');
    expect(reflectionBand(0.3999).id).toBe('some');
    expect(reflectionBand(0.4).id).toBe('lots');
    expect(reflectionBand(1).id).toBe('lots');
    expect(REFLECTION_BANDS.map(bandLabel)).toEqual(['little reflection', 'some reflection', 'lots of reflection']);
  });
  it('R falls as the view rises', () => {
    const { elevation, R, T } = splitByElevation(1.333);
    expect(elevation[0]).toBe(1);
    expect(elevation.at(-1)).toBe(90);
    for (let i = 1; i < R.length; i += 1) expect(R[i]).toBeLessThan(R[i - 1]);
    expect(T.every((t, i) => t + R[i] === 1)).toBe(true);
  });
});

describe('the floor seen from the air', () => {
  it('is weighed by T/n², the radiance of light spread into the wider cone above the surface', () => {
    // Étendue: n² dA cos θ dω is kept across a refraction, so L/n² is too (Nicodemus 1963; Pharr et al., PBRT 3rd ed.,
    // §16.1.3). Leaving water into air, dω grows by n² for the same flux: the radiance falls by 1/n².
    for (const [e, n] of [[90, 1.333], [30, 1.5], [5, 2.4]]) {
      const ray = centreRay(e, n);
      const T = 1 - dielectricR(cosOfDegrees(90 - e), 1, n);
      expect(ray.floorWeight).toBeCloseTo(T / (n * n), 12);
    }
    expect(centreRay(90, 1.333).floorWeight).toBeCloseTo(0.5513, 4); // water head-on: 0.98 of the light, 0.56 of it per solid angle
  });
});

describe('the captions in another language', () => {
  usePseudoLocale();
  it('come from the catalogue when they are read', () => {
    for (const band of [...REFLECTION_BANDS, reflectionBand(0)]) {
      expect(bandLabel(band).startsWith('⟦'), band.id).toBe(true);
      expect(wordsOutside(bandLabel(band)), band.id).toBe('');
    }
    expect(bandLabel(centreRay(60, 1.333).band)).toMatch(/^⟦/);
  });
});
