// The embed page's link (src/host/embedLink.js), which the share link, the composer's preview and a
// deck's frames all write: what it writes, and that the embed page reads back from it the view and
// the options it was given (the panel's values through src/host/params.js, the page's own options
// through src/host/readEmbedOptions.js).
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { embedLink } from '../../src/host/embedLink.js';
import { readParams } from '../../src/host/params.js';
import { readEmbedOptions } from '../../src/host/readEmbedOptions.js';
import { schema as schlickSchema } from '../../src/panels/schlick/schema.js';
import { check } from './fuzzConfig.js';
import { forAnyPanel, validView } from './schemaArbitraries.js';

const schlick = { id: 'schlick', schema: schlickSchema };

describe('the embed link', () => {
  it('is the panel alone where every value is its default', () => {
    expect(embedLink('embed.html', schlick)).toBe('embed.html?panel=schlick');
    expect(embedLink('embed.html', schlick, { nT: schlickSchema.nT.default })).toBe('embed.html?panel=schlick');
  });
  it('writes the values that differ, then lock, hide, theme, projector, fit and lang, with their commas as written', () => {
    expect(embedLink('https://lab.example/fresnel-lab/embed.html', schlick, { nT: 1.7 }, {
      lock: ['nI', 'nT'], hide: ['theta'], theme: 'light', projector: true, fit: true, lang: 'es',
    })).toBe('https://lab.example/fresnel-lab/embed.html?panel=schlick&nT=1.7&lock=nI,nT&hide=theta&theme=light&projector=1&fit=1&lang=es');
  });
  it('keeps a query the address has already, and leaves out the options that say nothing', () => {
    expect(embedLink('offline/embed.html?x=1', schlick, {}, { theme: null, projector: false, fit: false, lang: null }))
      .toBe('offline/embed.html?x=1&panel=schlick');
  });

  it('reads back on the embed page as the view and the options it was written with, for every panel', () => {
    const written = (schema) => fc.record({
      view: validView(schema),
      base: fc.constantFrom('embed.html', 'offline/embed.html', 'https://lab.example/lab/embed.html', 'embed.html?x=1'),
      lock: fc.subarray(Object.keys(schema)),
      hide: fc.subarray(Object.keys(schema)),
      theme: fc.constantFrom(null, 'light', 'dark'),
      projector: fc.boolean(),
      fit: fc.boolean(),
      lang: fc.constantFrom(null, 'en', 'es', 'ar-XB'),
    });
    check(fc.property(forAnyPanel(written), ([id, schema, { view, base, ...options }]) => {
      const link = embedLink(base, { id, schema }, view, options);
      const search = new URL(link, 'https://reader.example/deck/').searchParams;
      expect(search.get('panel')).toBe(id);
      expect(readParams(schema, search)).toEqual({ values: view, problems: [] });
      const read = readEmbedOptions(search);
      expect(read.problems).toEqual([]);
      expect(read.options).toMatchObject({
        lock: options.lock, hide: options.hide, theme: options.theme, projector: options.projector || null, fit: options.fit,
      });
      expect(search.get('lang')).toBe(options.lang);
      if (base.includes('?x=1')) expect(search.get('x')).toBe('1');
    }), 150);
  });
});
