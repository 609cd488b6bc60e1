// Every number in a lede (src/panels/manifest.js) is checked here against the code its panel uses,
// so an explanation cannot drift from its panel. A lede with a number and no check here fails the
// last test.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { PANELS } from '../../src/panels/manifest.js';
import { SCENE, sheenGrowth, specularAlbedo } from '../../src/panels/asphalt/physics.js';
import { schema as asphaltSchema } from '../../src/panels/asphalt/schema.js';
import { defaults } from '../../src/host/params.js';
import { dielectricById, metalF0, metals } from '../../src/optics/materials.js';
import { normalIncidence } from '../../src/optics/fresnel.js';
import { NEUTRAL } from '../../src/panels/metals/words.js';
import { metalCurves, metalCurveStats } from '../../src/panels/metals/physics.js';

const plain = (html) => html.replace(/<[^>]+>/g, '').replace(/\s+/g, ' ');
const words = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../locales/en.json'), 'utf8')).panels;
const lede = (id) => plain(words[`${id}.lede`]);
const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);

describe('the numbers in the ledes are the panels\' own', () => {
  it('asphalt: from the road straight below to the horizon the lobe gives about 19×, F about 12×; 7 % reflected at a 10° sun', () => {
    const values = defaults(asphaltSchema);
    expect(values.sunEl).toBe(10);
    // Two stated directions, not two frames: any camera that has the horizon in view gives the same factors.
    for (const camEl of [values.camEl, 12]) {
      const growth = sheenGrowth({ ...values, camEl }, 2);
      expect(growth.spot.below).toBeLessThan(1e-6); // the brightest spot is at the horizon
      expect(growth.reference.below).toBeCloseTo(90, 9); // against the road straight below
      expect(lede('asphalt')).toContain(`makes the specular light about ${Math.round(growth.lobe)}× brighter`);
      expect(lede('asphalt')).toContain(`and the half-vector rises about ${Math.round(growth.fresnel)}×`);
    }
    expect(sheenGrowth({ ...values, fresnel: false }, 2).fresnel).toBe(1); // with Fresnel off, only the lobe grows
    expect(lede('asphalt')).toContain('From the road straight below you to the road at the horizon, with the sun 10° up');
    expect(lede('asphalt')).toContain(`with the sun ${values.sunEl}° up the road reflects only about `
      + `${Math.round(100 * specularAlbedo(values))} % of the sunlight specularly`);
    expect(lede('asphalt')).toContain(`diffuse albedo of ${Math.round(100 * SCENE.albedo)} %`);
    expect(specularAlbedo(values)).toBeLessThan(SCENE.albedo);
    // Not at every sun the slider gives: which is why the lede names its sun.
    expect(specularAlbedo({ ...values, sunEl: 2 })).toBeGreaterThan(SCENE.albedo);
  });
  it('metals: 0.41 to 0.99 of the light head-on per channel; gold and copper coloured, silver, aluminium and iron nearly neutral', () => {
    const f0 = Object.fromEntries(metals.map((m) => [m.id, metalF0(m)]));
    const all = Object.values(f0).flat();
    expect(lede('metals')).toContain(`from ${Math.min(...all).toFixed(2)} to ${Math.max(...all).toFixed(2)} of the light per channel`);
    for (const id of ['gold', 'copper']) expect(spread(f0[id]), id).toBeGreaterThan(NEUTRAL);
    for (const id of ['silver', 'aluminium', 'iron']) expect(spread(f0[id]), id).toBeLessThan(NEUTRAL);
    expect(lede('metals')).toMatch(/colour for gold and copper, nearly neutral for silver, aluminium and iron/);
    // Towards grazing most channels dip below F0: aluminium's red deepest, by 0.08 near 82°; gold's blue not at all.
    const channels = metals.flatMap((m) => metalCurveStats(metalCurves(m), m).map((s) => ({ metal: m.id, ...s })));
    expect(channels.filter((c) => c.dip >= 0.001).length).toBeGreaterThan(channels.length / 2);
    const deepest = channels.reduce((a, b) => (b.dip > a.dip ? b : a));
    expect([deepest.metal, deepest.channel]).toEqual(['aluminium', 'red']);
    expect(lede('metals')).toContain(`R first dips below F0 in most channels (aluminium's red by ${deepest.dip.toFixed(2)}, `
      + `near ${deepest.minimum.theta.toFixed(0)}°; gold's blue not at all)`);
    expect(channels.find((c) => c.metal === 'gold' && c.channel === 'blue').dip).toBe(0);
    // Dielectrics: a few per cent head-on.
    for (const id of ['glass', 'acrylic', 'polycarbonate']) {
      const r0 = normalIncidence(1, dielectricById(id).n);
      expect(r0 > 0.02 && r0 < 0.06, id).toBe(true);
    }
  });
  it('refractive-index: glass of 1.5 reflects 0.04 in air and 0.0035 under water', () => {
    expect(normalIncidence(1, 1.5).toFixed(2)).toBe('0.04');
    expect(normalIncidence(dielectricById('water').n, 1.5).toFixed(4)).toBe('0.0035');
    expect(lede('refractive-index')).toContain('glass of 1.5 reflects 0.04 head-on in air but 0.0035 under water');
  });
  it('no lede holds a number this file does not check', () => {
    const checked = new Set(['asphalt', 'metals', 'refractive-index']);
    // Notation, and claims pinned where their code is tested: phrases stripped before looking for numbers.
    const accounted = [
      '(1 − F)', '(1 − R0)(1 − cos θ)5', 'R(0°)', 'R0', 'θ = 0', '[0, 1]', 'float64', '8-bit',
      'R + T = 1', // reflect-refract: R + T = 1, fresnel.test.js (Rs + Ts = 1, Rp + Tp = 1)
      'the reflectance is exactly 1', // exact-fresnel: R = 1 under total internal reflection, fresnel.test.js
    ];
    for (const entry of PANELS) {
      if (checked.has(entry.id)) continue;
      const text = accounted.reduce((t, phrase) => t.replaceAll(phrase, ''), lede(entry.id));
      expect(text.match(/\d+(?:\.\d+)?/g) ?? [], entry.id).toEqual([]);
    }
  });
});

describe('explanations in homework options hold', async () => {
  const { questionById } = await import('../../src/homework/questions.js');
  const { fresnelExact: F } = await import('../../src/optics/fresnel.js');
  it('rim scaling: the index barely moves a rim (F(85°) within 0.05 from n = 1.33 to 2)', () => {
    const rims = [1.33, 1.5, 2].map((n) => F(Math.cos((85 * Math.PI) / 180), 1, n));
    expect(Math.max(...rims) - Math.min(...rims)).toBeLessThan(0.05);
    const energy = questionById('rim-scaling').options({}).find((o) => o.id === 'energy');
    expect(energy.why({ nT: 1.5 })).toContain(`F(85°) = ${rims.map((r) => r.toFixed(2)).join(', ')} for n = 1.33, 1.5, 2`);
  });
});
