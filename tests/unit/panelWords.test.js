// The words of the dielectric and metal panels come from the message catalogue: in the pseudo-locale
// (every message ⟦bracketed⟧, scripts/pseudoLocale.js) no letter of a sentence, a name or a source
// they build is left outside the brackets, and in English they are what the data and the lecture say.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import fc from 'fast-check';
import pseudo from 'virtual:messages/en-XA';
import { wordsOutside as outside } from './inPseudoLocale.js';
import { setCatalogue } from '../../src/i18n/messages.js';
import { setNumberLocale } from '../../src/ui/format.js';
import { metalById, metals } from '../../src/optics/materials.js';
import { metalCurveStats, metalCurves } from '../../src/panels/metals/physics.js';
import { metalsLectureGap } from '../../src/panels/metals/words.js';
import { customRow, materialRows } from '../../src/panels/refractive-index/materialRows.js';
import { r0Steps } from '../../src/panels/r0-derivation/physics.js';
import { indexPresets } from '../../src/panels/shared/indexPresets.js';
import { CLASS_LABELS, classLabel } from '../../src/panels/shared/classLabels.js';
import { materialName, materialNameInText } from '../../src/panels/shared/materialName.js';
import { indexText } from '../../src/panels/shared/indexText.js';

const english = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../locales/en.json'), 'utf8'));
const data = JSON.parse(readFileSync(resolve(import.meta.dirname, '../../src/optics/materials.json'), 'utf8'));

const stats = (metal) => metalCurveStats(metalCurves(metal), metal);

// The language is the page's (module state shared by every test file of a worker): English again after each test.
afterEach(() => {
  setCatalogue('en', null);
  setNumberLocale('en');
});

describe('panel words in the pseudo-locale', () => {
  it('the metals note, every case of it, is the catalogue\'s words around numbers', () => {
    setCatalogue('en-XA', pseudo);
    for (const metal of metals) {
      const note = metalsLectureGap(metal, stats(metal));
      expect(note, metal.id).toMatch(/^⟦/);
      expect(outside(note), metal.id).toBe('');
    }
  });

  it('the material table\'s names and sources, the presets and the map classes', () => {
    setCatalogue('en-XA', pseudo);
    for (const row of [...materialRows(), customRow(1.7)]) {
      expect(outside(row.name), row.id).toBe('');
      expect(outside(row.source), row.id).toBe('');
    }
    for (const option of Object.keys(indexPresets().options)) expect(outside(option), option).toBe('');
    for (const cls of Object.keys(CLASS_LABELS)) expect(CLASS_LABELS[cls]).toBe(classLabel(cls));
    expect(CLASS_LABELS.fine).toMatch(/^⟦.*⟧$/);
  });
});

describe('panel words in English', () => {
  it('every material of materials.json is named in the catalogue as the data names it', () => {
    for (const entry of [...data.dielectrics, ...data.metals]) expect(materialName(entry.id), entry.id).toBe(entry.name);
    // Inside a sentence a metal is written in lower case ("for silver it is close").
    expect(materialNameInText('silver')).toBe('silver');
    expect(materialNameInText('water')).toBe('Water (20 °C)');
  });

  it('the table shows each dielectric\'s source as the data gives it', () => {
    const rows = materialRows();
    for (const entry of data.dielectrics) expect(rows.find((r) => r.id === entry.id).source, entry.id).toBe(entry.source);
  });

  it('every step of the R(0°) derivation has its words, each its own', () => {
    const { setup, lines } = r0Steps(1, 1.5);
    const keys = [...setup, ...lines].map((s) => `step.${s.step}`);
    for (const key of keys) expect(english['r0-derivation'], key).toHaveProperty([key]);
    expect(new Set(keys.map((key) => english['r0-derivation'][key])).size).toBe(keys.length);
  });

  it('the presets name the lecture\'s values and the measured dielectrics with their index', () => {
    const options = indexPresets().options;
    expect(options['Vacuum (1)']).toBe('vacuum');
    expect(options['Glass (lecture) (1.5)']).toBe('glass-1.5');
    expect(options['Crown glass (N-BK7) (1.5167)']).toBe('glass');
    expect(options.Custom).toBe('custom');
    expect(metalsLectureGap(metalById('gold'), stats(metalById('gold')))).toContain("towards grazing gold's R first dips");
  });
});

describe('indexText', () => {
  it('writes an index as JavaScript does, with the page\'s decimal separator', () => {
    fc.assert(fc.property(fc.integer({ min: 10_000, max: 30_000 }), fc.integer({ min: 0, max: 6 }), (whole, decimals) => {
      const n = Number((whole / 10_000).toFixed(decimals));
      setNumberLocale('en');
      expect(indexText(n)).toBe(String(n));
      setNumberLocale('es');
      expect(indexText(n)).toBe(String(n).replace('.', ','));
    }));
    setNumberLocale('en');
    expect([1, 1.5, 1.000293, 2.4166].map(indexText)).toEqual(['1', '1.5', '1.000293', '2.4166']);
  });
});
