// safeLocale: what browsers report on real systems, as ECMA-402 needs it; and for any input at
// all, never a throw and always a tag that every Intl constructor takes. pageLocale: dates follow
// the page's language, not the browser's, in the browser's own form of it where it speaks it.
import { afterEach, describe, expect, it, vi } from 'vitest';
import fc from 'fast-check';
import { FALLBACK_LOCALE, localeFor, pageLocale, safeLocale, setPageLanguage } from '../../src/ui/safeLocale.js';
import { useLanguage } from '../../src/i18n/language.js';
import { check } from './fuzzConfig.js';

/** The tag is canonical and each constructor the lab uses takes it. */
function accepted(tag) {
  expect(typeof tag).toBe('string');
  expect(Intl.getCanonicalLocales(tag)).toEqual([tag]);
  expect(() => [new Intl.NumberFormat(tag), new Intl.DateTimeFormat(tag), new Intl.Collator(tag), (0).toLocaleString(tag)]).not.toThrow();
}

describe('safeLocale: what browsers report', () => {
  it.each([
    ['en-US@posix', 'en-US'], // Chromium on Linux under LANG=C.UTF-8
    ['C', 'en'],
    ['C.UTF-8', 'en'],
    ['POSIX', 'en'],
    ['c', 'en'],
    ['', 'en'],
    ['   ', 'en'],
    ['en_US.UTF-8', 'en-US'],
    ['de_DE', 'de-DE'],
    ['de_DE.ISO-8859-1@euro', 'de-DE'],
    ['sr_RS@latin', 'sr-RS'],
    ['zh_Hant_TW', 'zh-Hant-TW'],
    ['en-us', 'en-US'],
    ['EN_gb', 'en-GB'],
    ['tr-TR', 'tr-TR'],
    ['ar-EG', 'ar-EG'],
    ['he', 'he'],
    ['iw', 'he'], // the old code for Hebrew, still reported by some systems
    ['en-US-u-nu-arab', 'en-US-u-nu-arab'],
    ['not a language', 'en'],
    ['x-private', 'en'],
    ['de-DE-', 'en'],
  ])('%j gives %j', (reported, expected) => {
    expect(safeLocale(reported)).toBe(expected);
    accepted(safeLocale(reported));
  });

  it('takes the first usable tag of a list, in order of preference', () => {
    expect(safeLocale(['en-US@posix', 'de'])).toBe('en-US');
    expect(safeLocale(['', 'not a language', 'fr_CA.UTF-8'])).toBe('fr-CA');
    expect(safeLocale(['C', 'de'])).toBe('en'); // C is a choice: English
    expect(safeLocale([])).toBe('en');
  });

  it('gives English for what is no tag at all', () => {
    for (const reported of [undefined, null, 42, {}, ['x'.repeat(1e4)], 'de'.padEnd(200, '-DE')]) {
      expect(safeLocale(reported)).toBe(FALLBACK_LOCALE);
    }
  });

  it('pageLocale is English without a browser (Node 20 has no navigator) and otherwise safe', () => {
    const tag = pageLocale();
    if (!globalThis.navigator) expect(tag).toBe('en');
    accepted(tag);
  });
});

// Strings made of the pieces POSIX names and BCP 47 tags are made of, so that runs reach tags
// that nearly read, beside any string at all.
const piece = fc.constantFrom('en', 'de', 'zh', 'C', 'POSIX', 'posix', 'US', 'DE', 'Hant', 'u', 'nu', 'arab', 'x', '1234', 'latin',
  'UTF-8', '');
const separator = fc.constantFrom('-', '_', '.', '@', ' ', '');
const tagLike = fc.array(fc.tuple(piece, separator), { maxLength: 6 }).map((parts) => parts.flat().join(''));
const reported = fc.oneof(fc.string({ unit: 'binary', maxLength: 120 }), tagLike, fc.anything());

describe('safeLocale: any input', () => {
  it('never throws and always gives a canonical tag every Intl constructor takes', () => {
    check(fc.property(fc.oneof(reported, fc.array(reported, { maxLength: 20 })), (input) => {
      accepted(safeLocale(input));
    }), 300);
  });

  it('keeps a tag that is already canonical (but POSIX, a well-formed tag that names the portable locale)', () => {
    check(fc.property(tagLike, (text) => {
      let canonical;
      try {
        [canonical] = Intl.getCanonicalLocales(text);
      } catch {
        return; // not a tag
      }
      if (canonical) expect(safeLocale(canonical)).toBe(canonical === 'posix' ? 'en' : canonical);
    }), 300);
  });
});

describe('the locale of dates and times: the page\'s language', () => {
  afterEach(() => {
    setPageLanguage(null);
    vi.unstubAllGlobals();
  });

  it.each([
    ['es', ['en-US'], 'es'], // a Spanish page in an American browser writes Spanish dates
    ['es', ['en-US', 'es-MX'], 'es-MX'], // in the browser's own form of Spanish where it has one
    ['en', ['en-GB', 'en-US'], 'en-GB'],
    ['en', ['de-DE', 'en-US@posix'], 'en-US'],
    ['es', ['es_ES.UTF-8'], 'es-ES'],
    ['en', ['C'], 'en'],
    ['es', [], 'es'],
    ['es', 'not a language', 'es'],
    ['not a language', ['de-DE'], 'en'], // a language that is no tag is English, never a throw
    [undefined, undefined, 'en'],
  ])('%j in a browser reporting %j is written %j', (language, reported, expected) => {
    expect(localeFor(language, reported)).toBe(expected);
    accepted(localeFor(language, reported));
  });

  it('any language and anything reported give a tag every Intl constructor takes', () => {
    check(fc.property(reported, fc.oneof(reported, fc.array(reported, { maxLength: 20 })), (language, browser) => {
      accepted(localeFor(language, browser));
    }), 300);
  });

  it('follows the language the page chose, not the browser\'s, once the page has one', async () => {
    vi.stubGlobal('navigator', { languages: ['en-US'], language: 'en-US' });
    vi.stubGlobal('document', { documentElement: {} });
    const december = (locale) => new Intl.DateTimeFormat(locale, { month: 'long', timeZone: 'UTC' }).format(new Date('2026-12-05T12:00:00Z'));
    expect(pageLocale()).toBe('en-US');
    try {
      await useLanguage('es'); // as a page in Spanish starts (src/i18n/language.js)
      expect(pageLocale()).toBe('es');
      expect(december(pageLocale())).toBe('diciembre');
      await useLanguage('en-XA'); // a pseudo-locale writes its dates as its numbers: English
      expect(pageLocale()).toBe('en-US');
    } finally {
      await useLanguage('en');
    }
    expect(december(pageLocale())).toBe('December');
  });
});
