// Every number in a lede (src/panels/manifest.js) is checked here against the code its panel uses,
// so an explanation cannot drift from its panel. A lede with a number and no check here fails the
// last test.
import { describe, expect, it } from 'vitest';
import { PANELS, panelEntry } from '../../src/panels/manifest.js';
import { SCENE, sheenGrowth, specularAlbedo } from '../../src/panels/asphalt/model.js';
import { schema as asphaltSchema } from '../../src/panels/asphalt/schema.js';
import { defaults } from '../../src/host/params.js';
import { dielectricById, metalF0, metals } from '../../src/optics/materials.js';
import { normalIncidence } from '../../src/optics/fresnel.js';
import { NEUTRAL } from '../../src/panels/metals/lectureGap.js';

const plain = (html) => html.replace(/<[^>]+>/g, '').replace(/\s+/g, ' ');
const lede = (id) => plain(panelEntry(id).lede);
const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);

describe('the numbers in the ledes are the panels\' own', () => {
  it('asphalt: the lobe grows about 13× and F 9.5× from overhead to 6°; 7 % reflected specularly, against a 9 % albedo', () => {
    const values = defaults(asphaltSchema);
    expect(values.camEl).toBe(6);
    const growth = sheenGrowth({ ...values, fresnel: false }, 2);
    const withF = sheenGrowth(values, 2);
    expect(lede('asphalt')).toContain(`about ${Math.round(growth.lobe)}× from overhead to a camera ${values.camEl}° up`);
    expect(lede('asphalt')).toContain(`(another ${withF.fresnel.toFixed(1)}×)`);
    expect(lede('asphalt')).toContain(`about ${Math.round(100 * specularAlbedo(values))} % of the sunlight specularly`);
    expect(lede('asphalt')).toContain(`diffuse albedo of ${Math.round(100 * SCENE.albedo)} %`);
    expect(specularAlbedo(values)).toBeLessThan(SCENE.albedo);
  });
  it('metals: 0.41 to 0.99 of the light head-on per channel; gold and copper coloured, silver, aluminium and iron nearly neutral', () => {
    const f0 = Object.fromEntries(metals.map((m) => [m.id, metalF0(m)]));
    const all = Object.values(f0).flat();
    expect(lede('metals')).toContain(`from ${Math.min(...all).toFixed(2)} to ${Math.max(...all).toFixed(2)} of the light per channel`);
    for (const id of ['gold', 'copper']) expect(spread(f0[id]), id).toBeGreaterThan(NEUTRAL);
    for (const id of ['silver', 'aluminium', 'iron']) expect(spread(f0[id]), id).toBeLessThan(NEUTRAL);
    expect(lede('metals')).toMatch(/colour for gold and copper, nearly neutral for silver, aluminium and iron/);
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
      '(1 − F)', '(1 − R0)(1 − cos θ)5', 'R(0°)', 'R0', 'θ = 0', '[0, 1]', 'float64',
      'R + T = 1', // reflect-refract: R + T = 1, fresnel.test.js (Rs + Ts = 1, Rp + Tp = 1)
      'the reflectance is exactly 1', // exact-fresnel: R = 1 under total internal reflection, fresnel.test.js
    ];
    for (const entry of PANELS) {
      if (checked.has(entry.id)) continue;
      const text = accounted.reduce((t, phrase) => t.replaceAll(phrase, ''), plain(entry.lede));
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
