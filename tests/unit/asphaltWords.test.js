// What the asphalt panel says (src/panels/asphalt/words.js), held against the road shaded from the
// textbook formulas (tests/unit/oracle/roadOracle.js): how concentrated the reflected light is does
// not depend on the camera, and where nothing is reflected the panel says so instead of naming a
// highlight.
import { describe, expect, it } from 'vitest';
import {
  brightestSightLine, highlightInView, sheenGrowth, specularAlbedo,
} from '../../src/panels/asphalt/physics.js';
import { describeRoad, readoutText, summaryRows } from '../../src/panels/asphalt/words.js';
import { SUN, luminance, roadLight, roadSpot, specularAlbedoByDirections, sunVector } from './oracle/roadOracle.js';

const DEG = Math.PI / 180;
const base = { camEl: 6, sunEl: 10, roughness: 0.8, nT: 1.55, fresnel: true };

/** What the panel's words are made of, as index.js gathers it. */
function road(values) {
  const { peak, centre } = highlightInView(values, 2);
  return {
    values, peak, centre, growth: sheenGrowth(values, 2), albedo: specularAlbedo(values), brightest: brightestSightLine(values),
  };
}

/** The brightest the sun's highlight is from any sight line in the sun's plane: a 0.01° scan, the horizon limit included. */
function brightestByScan(values) {
  let best = { specular: roadSpot(1e-6, values).specular, below: 0 };
  for (let i = 1; i < 18000; i += 1) {
    const { specular } = roadSpot(i / 100, values);
    if (specular > best.specular) best = { specular, below: i / 100 };
  }
  return best;
}

/** The concentration the words should give: the brightest luminance over a matte road reflecting the same share. */
function concentrationByFormula(values) {
  const matte = (specularAlbedoByDirections(values, 200) * luminance(SUN) * sunVector(values.sunEl)[1]) / Math.PI;
  return brightestByScan(values).specular / matte;
}

/** The number a shape clause states ("… has 90.4 times the luminance of a matte …"). */
const statedConcentration = (text) => Number(/has (?:only )?([\d.]+) times the luminance of a matte \(Lambertian\) road/.exec(text)?.[1]);

describe('how concentrated the reflected light is', () => {
  const settings = [
    base,
    { ...base, sunEl: 45, roughness: 0.2 }, // a glossy road under a high sun: the peak is the mirror direction
    { ...base, sunEl: 45, roughness: 1 },
    { ...base, sunEl: 2 },
    { ...base, fresnel: false },
  ];
  it('is the brightest sight line against a matte road reflecting as much, the same from every camera elevation', () => {
    for (const values of settings) {
      const expected = concentrationByFormula(values);
      const clauses = [2, 6, 20, 45, 60, 90].map((camEl) => {
        const text = describeRoad(road({ ...values, camEl }));
        return text.slice(text.indexOf('that light is'));
      });
      expect(new Set(clauses).size, JSON.stringify(values)).toBe(1);
      const stated = statedConcentration(clauses[0]);
      expect(Math.abs(stated - expected), `${clauses[0]} against ${expected}`).toBeLessThanOrEqual(0.05 + 1e-3 * expected);
      expect(clauses[0]).toContain(expected >= 3 ? 'that light is concentrated:' : 'that light is spread out');
    }
    // The default road's light is concentrated, overhead as well as near grazing: 90.4 times at the horizon.
    const text = describeRoad(road({ ...base, camEl: 90 }));
    expect(text).toContain('that light is concentrated: seen from its brightest direction, towards the horizon (in the limit as the line '
      + 'of sight grazes the road), the sun\'s highlight '
      + `has ${concentrationByFormula(base).toFixed(1)} times the luminance`);
    // Low over the road the brightest spot in view is the horizon's, a limit no sight line along the road reaches.
    expect(describeRoad(road(base))).toContain('the brightest highlight in view, seen at the horizon, has specular luminance');
    expect(describeRoad(road({ ...base, camEl: 90 }))).toMatch(/the brightest highlight in view, seen \d+\.\d° below the horizon,/);
    // A smooth road is brightest near the mirror direction, below the horizon: the words name that angle.
    const smooth = { ...base, roughness: 0.2 };
    const below = brightestByScan(smooth).below;
    expect(below).toBeGreaterThan(5);
    expect(describeRoad(road(smooth))).toContain(`seen from its brightest direction, ${below.toFixed(1)}° below the horizon, `);
  });
  it('its brightest direction is the brightest over the whole sky of sight lines, not only the sun\'s plane', () => {
    for (const values of settings) {
      const inPlane = brightestByScan(values);
      expect(brightestSightLine(values).specular / inPlane.specular).toBeGreaterThan(1 - 1e-6);
      for (let i = 1; i <= 89; i += 1) {
        for (let j = 1; j < 180; j += 2) {
          const [el, az] = [i * DEG, j * DEG];
          const v = [Math.cos(el) * Math.sin(az), Math.sin(el), -Math.cos(el) * Math.cos(az)];
          expect(roadLight(v, values).specular).toBeLessThanOrEqual(inPlane.specular * (1 + 1e-9));
        }
      }
    }
  });
});

describe('a road that reflects nothing specularly is said to', () => {
  const terms = (rows) => rows.map(([term]) => term);
  it('with n_t = 1: no "brightest highlight", no ratio, a sentence instead', () => {
    for (const fresnel of [true, false]) {
      const values = { ...base, nT: 1, fresnel };
      expect(brightestByScan(values).specular).toBeLessThan(1e-20); // F = R0 = 0 at every angle, to rounding
      const rows = summaryRows(road(values));
      expect(terms(rows)).not.toContain('Brightest highlight in view');
      expect(terms(rows)).not.toContain('Highlight ÷ diffuse');
      expect(rows).toContainEqual(['Specular reflection', 'none: with n_t = 1 the binder matches air, so F = 0 at every angle', true]);
      const diffuse = roadSpot(30, values).diffuse;
      expect(rows).toContainEqual(['Diffuse road (the same from every direction)', diffuse.toFixed(3)]);
      expect(describeRoad(road(values))).toContain('With n_t = 1 the binder matches air: F = 0 at every angle (R0 = 0 too), so the road '
        + `has no specular reflection, only its diffuse part, ${diffuse.toFixed(3)} everywhere on the road`);
    }
  });
  it('with an index so near 1 that the highlight reads 0.000 from every direction, and not a hair further', () => {
    const near = { ...base, nT: 1.0001 };
    expect(brightestByScan(near).specular).toBeLessThan(0.0005);
    expect(summaryRows(road(near))).toContainEqual(['Specular reflection',
      'none to be seen: with n_t = 1.0001 the binder so nearly matches air that the sun\'s highlight reads 0.000 from every direction', true]);
    expect(describeRoad(road(near))).not.toContain('concentrated');
    const step = { ...base, nT: 1.001 }; // one step of the control
    expect(brightestByScan(step).specular).toBeGreaterThan(0.0005);
    expect(terms(summaryRows(road(step)))).toContain('Brightest highlight in view');
  });
  it('with Fresnel off, blames the switch and not the index: the same binder with Fresnel on has a highlight', () => {
    const off = { ...base, nT: 1.03, fresnel: false };
    expect(brightestByScan(off).specular).toBeLessThan(0.0005); // F held at R0 = (0.03 / 2.03)² ≈ 2.2e−4
    expect(brightestByScan({ ...off, fresnel: true }).specular).toBeGreaterThan(0.1); // F rising towards grazing
    const r0 = '2.2e\u22124';
    expect(summaryRows(road(off))).toContainEqual(['Specular reflection', `none to be seen: with Fresnel off, F is held at R0 = ${r0} `
      + '(n_t = 1.03), so small that the sun\'s highlight reads 0.000 from every direction', true]);
    const text = describeRoad(road(off));
    expect(text).toContain(`With Fresnel off, F is held at its head-on value R0 = ${r0} (n_t = 1.03)`);
    expect(text).toContain('reads 0.000 from every direction (with Fresnel on, F would rise towards 1 as the light grazes the microfacets), '
      + `so the road shows only its diffuse part, ${roadSpot(30, off).diffuse.toFixed(3)} everywhere on the road`);
    expect(text).not.toContain('so nearly matches air');
    expect(terms(summaryRows(road({ ...off, fresnel: true })))).toContain('Brightest highlight in view');
  });
});

describe('the hover readout', () => {
  it('gives the angle below the horizon to 0.1° and both parts to 3 decimals (the homework question\'s tolerance rests on it)', () => {
    const hit = { distance: 12.34, below: 43.92, thetaD: 63.06, F: 0.1234, specular: 0.03434, diffuse: 0.03431 };
    expect(readoutText(hit)).toBe('Road 12.3 m ahead, seen 43.9° below the horizon: θd = 63.1°, F = 0.123, sun\'s highlight 0.034, '
      + 'diffuse 0.034');
    expect(readoutText(null)).toBe('Sky: no road under the cursor.');
  });
});
