// The one HTML escaper (src/ui/escapeHtml.js): decks, offline lectures, embed snippets, the
// lecture page's headings and the pages' words at build time all write text through it.
import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { escapeHtml } from '../../src/ui/escapeHtml.js';
import { decodeEntities } from '../../src/i18n/richText.js';
import { anyText } from './fuzzArbitraries.js';
import { check } from './fuzzConfig.js';

describe('escapeHtml', () => {
  it('writes & < > " \' as entities and leaves the rest', () => {
    expect(escapeHtml(`<a href="x" title='y'>R & T</a> θ ≈ 0.04`))
      .toBe('&lt;a href=&quot;x&quot; title=&#39;y&#39;&gt;R &amp; T&lt;/a&gt; θ ≈ 0.04');
    expect(escapeHtml('&amp;')).toBe('&amp;amp;'); // an entity in the text is text too
    expect(escapeHtml(42)).toBe('42');
  });
  it('any text: nothing that opens a tag or ends a quoted value, and it reads back as the text', () => {
    check(fc.property(anyText, (text) => {
      const html = escapeHtml(text);
      expect(html).not.toMatch(/[<>"']/);
      expect(html.replace(/&(amp|lt|gt|quot|#39);/g, '')).not.toContain('&');
      expect(decodeEntities(html)).toBe(text);
    }), 200);
  });
});
