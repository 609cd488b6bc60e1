// Every number in a lede (locales/en.json, panels → <id>.lede) comes from the code its panel uses,
// so an explanation cannot drift from its panel: a panel whose lede states a number has a module
// src/panels/<id>/ledeNumbers.js that writes each such phrase from the panel's physics or data, and the
// lede must hold every phrase and no other number. A new panel needs no edit here: its lede either
// states none, or its folder says where they come from. Notation is no number: digits in a name
// (R0, F0, float64, 8-bit), in an exponent or a subscript (markup), and 0 and 1, the ends of every
// fraction (R + T = 1, [0, 1], θ = 0, 1 − F), whose claims are tested where their code is
// (fresnel.test.js: R + T = 1, R = 1 under total internal reflection).
// What a lede says in words about those numbers is checked below them.
import { existsSync, readFileSync } from 'node:fs';
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

const root = resolve(import.meta.dirname, '../..');
const plain = (html) => html.replace(/<[^>]+>/g, '').replace(/\s+/g, ' ');
const words = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8')).panels;
const lede = (id) => plain(words[`${id}.lede`]);
const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);

/** The phrases with numbers a panel's folder writes for its lede ([] for a panel without ledeNumbers.js). */
async function ledeNumbers(id) {
  const path = resolve(root, `src/panels/${id}/ledeNumbers.js`);
  return existsSync(path) ? (await import(path)).ledeNumbers() : [];
}

/** The numbers left in a lede once its phrases and its notation are taken out. */
function unaccountedNumbers(ledeHtml, phrases) {
  const text = phrases.reduce((t, phrase) => t.replaceAll(phrase, ' '),
    plain(ledeHtml.replace(/<(sup|sub)>[^<]*<\/\1>/g, '')));
  return (text.replace(/\p{L}+\d+|\d+-\p{L}+/gu, '').match(/\d+(?:\.\d+)?/g) ?? []).filter((n) => n !== '0' && n !== '1');
}

describe('the numbers in the ledes are the panels\' own', () => {
  it.each(PANELS.map((p) => p.id))('%s: each phrase its ledeNumbers.js writes, and no other number', async (id) => {
    const phrases = await ledeNumbers(id);
    for (const phrase of phrases) expect(lede(id), `src/panels/${id}/ledeNumbers.js`).toContain(phrase);
    expect(unaccountedNumbers(words[`${id}.lede`], phrases), `numbers in ${id}.lede that no src/panels/${id}/ledeNumbers.js phrase writes`)
      .toEqual([]);
  });
  it('notation is no number; a quantity, a decimal or a number beside a unit is', () => {
    expect(unaccountedNumbers('R0, F0, float64, an 8-bit display, (1 − cos θ)<sup>5</sup>, n<sub>12</sub>, [0, 1], R(0°)', [])).toEqual([]);
    expect(unaccountedNumbers('about 19× brighter, 0.04 head-on, 7 %, near 82°, 1.5', [])).toEqual(['19', '0.04', '7', '82', '1.5']);
    expect(unaccountedNumbers('it reflects 0.04 head-on', ['reflects 0.04 head-on'])).toEqual([]);
  });
});

describe('what the ledes say in words about their numbers holds', () => {
  it('asphalt: the factors hold for any view of the horizon; with Fresnel off only the lobe grows; the share is the named sun\'s', () => {
    const values = defaults(asphaltSchema);
    // Two stated directions, not two frames: any camera that has the horizon in view gives the same factors.
    const [a, b] = [values.camEl, 12].map((camEl) => sheenGrowth({ ...values, camEl }, 2));
    expect([Math.round(b.lobe), Math.round(b.fresnel)]).toEqual([Math.round(a.lobe), Math.round(a.fresnel)]);
    for (const growth of [a, b]) {
      expect(growth.spot.below).toBeLessThan(1e-6); // the brightest spot is at the horizon
      expect(growth.reference.below).toBeCloseTo(90, 9); // against the road straight below
    }
    expect(lede('asphalt')).toContain('(with Fresnel off, that is all that grows)');
    expect(sheenGrowth({ ...values, fresnel: false }, 2).fresnel).toBe(1);
    expect(lede('asphalt')).toContain('less than its diffuse albedo');
    expect(specularAlbedo(values)).toBeLessThan(SCENE.albedo);
    // Not at every sun the slider gives: which is why the lede names its sun.
    expect(specularAlbedo({ ...values, sunEl: 2 })).toBeGreaterThan(SCENE.albedo);
  });
  it('metals: gold and copper coloured, silver, aluminium and iron nearly neutral; most channels dip, gold\'s blue not at all', () => {
    const f0 = Object.fromEntries(metals.map((m) => [m.id, metalF0(m)]));
    for (const id of ['gold', 'copper']) expect(spread(f0[id]), id).toBeGreaterThan(NEUTRAL);
    for (const id of ['silver', 'aluminium', 'iron']) expect(spread(f0[id]), id).toBeLessThan(NEUTRAL);
    expect(lede('metals')).toMatch(/colour for gold and copper, nearly neutral for silver, aluminium and iron/);
    const channels = metals.flatMap((m) => metalCurveStats(metalCurves(m), m).map((s) => ({ metal: m.id, ...s })));
    expect(lede('metals')).toContain('R first dips below F0 in most channels');
    expect(channels.filter((c) => c.dip >= 0.001).length).toBeGreaterThan(channels.length / 2);
    expect(lede('metals')).toContain('gold\'s blue not at all');
    expect(channels.find((c) => c.metal === 'gold' && c.channel === 'blue').dip).toBe(0);
    // Dielectrics: a few per cent head-on.
    expect(lede('metals')).toContain('Plastic, glass and paint reflect a few per cent head-on');
    for (const id of ['glass', 'acrylic', 'polycarbonate']) {
      const r0 = normalIncidence(1, dielectricById(id).n);
      expect(r0 > 0.02 && r0 < 0.06, id).toBe(true);
    }
  });
  it('refractive-index: its head-on numbers are the textbook R0 of glass of 1.5', () => {
    // Textbook: R0 = ((n_t − n_i)/(n_t + n_i))²; (0.5/2.5)² = 0.04, (0.1667/2.8333)² = 0.00346.
    expect(lede('refractive-index')).toContain('glass of 1.5 reflects 0.04 head-on in air but 0.0035 under water');
    expect(dielectricById('water').n).toBeCloseTo(1.3333, 4);
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
