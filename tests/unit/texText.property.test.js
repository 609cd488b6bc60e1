// Words from a catalogue inside a formula's \text{…}: KaTeX reads them as the words, whatever they
// hold (TeX's special characters, the pseudo-locale's brackets, another script); and the names of
// the functions, as the page's language writes them.
import { describe, it, expect } from 'vitest';
import fc from 'fast-check';
import katex from 'katex';
import { texText } from '../../src/ui/texText.js';
import { texMacros } from '../../src/ui/texMacros.js';
import { mathHtml } from '../../src/lecture/lectureTextHtml.js';
import { setCatalogue } from '../../src/i18n/messages.js';
import spanish from 'virtual:messages/es';
import pseudo from 'virtual:messages/en-XA';
import { check } from './fuzzConfig.js';

/**
 * The words KaTeX draws for `tex` (its HTML, tags dropped, entities read, spaces collapsed); it
 * draws ⟦ and ⟧ as two square brackets, kerned together.
 */
function drawnText(tex) {
  const html = katex.renderToString(tex, { throwOnError: true, strict: 'ignore', output: 'html' });
  return html.replace(/<[^>]*>/g, '')
    .replace(/&(amp|lt|gt|quot|#x27|#39);/g, (_, name) => ({ amp: '&', lt: '<', gt: '>', quot: '"', '#x27': "'", '#39': "'" })[name])
    .replace(/[\s\u00a0]+/g, ' ').trim().replaceAll('[[', '⟦').replaceAll(']]', '⟧');
}

describe('texText: catalogue words in a formula', () => {
  it('spells each character TeX reads as a command as text', () => {
    const special = 'a\\b{c}d$e&f#g_h%i^j~k';
    expect(drawnText(`\\text{${texText(special)}}`)).toBe(special);
    // KaTeX builds an accented letter from its base and the accent: the words typeset, accents apart.
    expect(drawnText(`\\text{${texText('⟦ƈöļöũŕ⟧')}}`)).toMatch(/^⟦ƈ.+⟧$/);
    expect(drawnText(`\\text{${texText('no hay rayo refractado')}}`)).toBe('no hay rayo refractado');
  });

  it('any words: KaTeX typesets them without an error and draws them as they are', () => {
    const words = fc.string({ unit: fc.constantFrom(...'abc XYZ\\{}$&#_%^~⟦⟧'), maxLength: 40 });
    check(fc.property(words, (text) => {
      expect(drawnText(`\\text{${texText(text)}}`)).toBe(text.replace(/\s+/g, ' ').trim());
    }));
  });
});

describe('texMacros: the functions\' names in the page\'s language', () => {
  const typeset = (tex, macros) => katex.renderToString(tex, { throwOnError: true, output: 'html', macros })
    .replace(/<[^>]*>/g, '').replace(/[\s\u00a0\u200b]+/g, '');

  it('English keeps TeX\'s sin; Spanish writes sen and arcsen; the pseudo-locale keeps TeX\'s', () => {
    expect(texMacros()).toEqual({});
    expect(drawnText('n_1 \\sin\\theta')).toMatch(/sin/);
    try {
      setCatalogue('es', spanish);
      expect(texMacros()).toEqual({ '\\sin': '\\operatorname{sen}', '\\arcsin': '\\operatorname{arcsen}' });
      expect(typeset('n_1 \\sin\\theta_1 = \\arcsin x', texMacros())).toBe('n1senθ1=arcsenx');
      // The lecturer's own math in a deck the lab writes, as on the page.
      expect(mathHtml('\\sin\\theta', false, 'html')).toContain('sen');
      setCatalogue('en-XA', pseudo);
      expect(texMacros()).toEqual({});
    } finally {
      setCatalogue('en', null);
    }
    expect(mathHtml('\\sin\\theta', false, 'html')).not.toContain('sen');
  });
});
