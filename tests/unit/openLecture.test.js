// Which lecture the lecture page opens (the link's, else the page's data element, else the lab's
// own), the keys of a composed lecture's items (a panel twice never shares a key or a URL prefix,
// its first item keeps the lab's own keys), and a schema whose defaults are an item's start state.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { itemKeys, openLecture } from '../../src/lecture/openLecture.js';
import { lectureToCode } from '../../src/lecture/lectureLink.js';
import { PANEL_IDS, lecturePrefix } from '../../src/panels/manifest.js';
import { panelSchema } from '../../src/panels/panelSchema.js';
import { readParams, withDefaults, writeParams } from '../../src/host/params.js';
import { check } from './fuzzConfig.js';

const lecture = (items) => ({ kind: 'fresnel-lab-lecture', version: 1, title: 'T', items });
const SCHLICK = { type: 'panel', panel: 'schlick', state: { nT: 1.33 } };
const TEXT = { type: 'text', text: 'Agenda' };
const schemaKeys = (id, prefix) => Object.keys(panelSchema(id)).map((k) => prefix + k);

describe('openLecture', () => {
  it('opens nothing without a lecture: the lab’s own', () => {
    const opened = openLecture(new URLSearchParams(''), null);
    expect(opened).toEqual({ source: 'default', lecture: null, problems: [], refused: false, given: null });
  });

  it('opens the link’s lecture, and it wins over one in the page', () => {
    const search = new URLSearchParams({ lecture: lectureToCode(lecture([SCHLICK])) });
    const opened = openLecture(search, JSON.stringify(lecture([TEXT])));
    expect(opened.source).toBe('link');
    expect(opened.lecture.items).toEqual([SCHLICK]);
  });

  it('opens the page’s lecture, naming what it leaves out', () => {
    const opened = openLecture(new URLSearchParams(''), JSON.stringify(lecture([TEXT, { type: 'panel', panel: 'nope' }])));
    expect(opened).toMatchObject({ source: 'data', refused: false, given: 'data' });
    expect(opened.lecture.items).toEqual([TEXT]);
    expect(opened.problems.join(' ')).toContain('nope is no panel');
  });

  it('refuses what cannot be read at all, and says where it came from', () => {
    const fromLink = openLecture(new URLSearchParams({ lecture: 'L1.@@' }), null);
    expect(fromLink).toMatchObject({ source: 'default', lecture: null, refused: true, given: 'link' });
    for (const text of ['{', '[]', 'null', JSON.stringify({ kind: 'other' }), ' '.repeat(400_001)]) {
      const opened = openLecture(new URLSearchParams(''), text);
      expect(opened, text.slice(0, 20)).toMatchObject({ source: 'default', lecture: null, refused: true, given: 'data' });
      expect(opened.problems.length).toBeGreaterThan(0);
    }
  });

  it('refuses a lecture with no item left to show, naming why', () => {
    const opened = openLecture(new URLSearchParams(''), JSON.stringify(lecture([{ type: 'panel', panel: 'nope' }])));
    expect(opened).toMatchObject({ source: 'default', lecture: null, refused: true, given: 'data' });
    expect(opened.problems.join(' ')).toMatch(/nope is no panel.*no item that can be shown/);
  });

  it('never throws on any page text', () => {
    check(fc.property(fc.string({ maxLength: 200 }), (text) => {
      const opened = openLecture(new URLSearchParams(''), text);
      expect(opened.given).toBe('data');
      expect(opened.refused || opened.lecture !== null).toBe(true);
    }));
  });
});

describe('itemKeys', () => {
  it('keeps the lab’s own keys for a panel’s first item, and numbers the later ones', () => {
    const items = [{ type: 'panel', panel: 'spheres' }, TEXT, { type: 'panel', panel: 'spheres' }, { type: 'question', question: 'q' },
      { type: 'panel', panel: 'schlick' }, { type: 'panel', panel: 'spheres' }];
    expect(itemKeys(items, lecturePrefix)).toEqual([
      { key: 'spheres', prefix: '' }, { key: 'text--2', prefix: null }, { key: 'spheres--2', prefix: 'spheres--2.' },
      { key: 'question--4', prefix: null }, { key: 'schlick', prefix: 'schlick.' }, { key: 'spheres--3', prefix: 'spheres--3.' },
    ]);
  });

  it('gives every item its own key and every panel item its own URL keys, none another panel’s', () => {
    const panel = fc.constantFrom(...PANEL_IDS).map((id) => ({ type: 'panel', panel: id }));
    const item = fc.oneof(panel, fc.constant(TEXT), fc.constant({ type: 'question' }));
    check(fc.property(fc.array(item, { maxLength: 30 }), (items) => {
      const keys = itemKeys(items, lecturePrefix);
      expect(new Set(keys.map((k) => k.key)).size).toBe(items.length);
      // Every URL key a panel item writes (prefix + schema key) is its alone.
      const urlKeys = keys.flatMap(({ prefix }, i) => (prefix === null ? [] : schemaKeys(items[i].panel, prefix)));
      expect(new Set(urlKeys).size).toBe(urlKeys.length);
      for (const { key } of keys) if (key.includes('--')) expect(PANEL_IDS).not.toContain(key);
    }));
  });
});

describe('withDefaults', () => {
  const schema = panelSchema('schlick');
  const start = { nT: 1.33 };
  it('reads an absent key as the item’s start, and writes only what differs from it', () => {
    const urlSchema = withDefaults(schema, start);
    expect(readParams(urlSchema, new URLSearchParams('')).values.nT).toBe(1.33);
    const search = writeParams(urlSchema, { ...readParams(urlSchema, new URLSearchParams('')).values, nT: 1.5 }, new URLSearchParams());
    expect(search.get('nT')).toBe('1.5'); // the panel's default, but not the item's start
    expect(writeParams(urlSchema, readParams(urlSchema, new URLSearchParams('')).values, new URLSearchParams()).toString()).toBe('');
    expect(schema.nT.default).toBe(1.5); // the panel's schema is left as it was
  });
});
