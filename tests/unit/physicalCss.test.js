// The check that every style sheet of the lab lays out by reading direction (scripts/physicalCss.js,
// which `npm run lint` runs over the sheets through scripts/lintLines.js) finds what it should.
import { describe, expect, it } from 'vitest';
import { directionProblems, physicalReason } from '../../scripts/physicalCss.js';

describe('what the check finds', () => {
  it('names physical sides, keywords and lopsided shorthands', () => {
    for (const [property, value] of [['margin-left', '1rem'], ['padding-right', '0'], ['border-left', '4px solid red'],
      ['border-right-color', 'red'], ['left', '0'], ['right', '1.5%'], ['text-align', 'right'], ['float', 'left'],
      ['clear', 'right'], ['padding', '0.2rem 0.8rem 0.2rem 0'], ['margin', '0 calc(1rem + 2px) 0 0'],
      ['border-radius', '6px 0 0 6px'], ['border-top-left-radius', '4px'], ['text-align', 'left !important']]) {
      expect(physicalReason(property, value), `${property}: ${value}`).not.toBeNull();
    }
  });

  it('passes logical and symmetric ones', () => {
    for (const [property, value] of [['margin-inline-start', '1rem'], ['padding-inline', '0 0.8rem'], ['inset-inline', '0'],
      ['text-align', 'start'], ['text-align', 'center'], ['padding', '0.2rem 0.8rem'], ['padding', '1px 2px 3px'],
      ['margin', '0 auto 0 auto'], ['border-radius', '6px'], ['border-radius', '50% / 10%'], ['inset', '0 0 auto 0'],
      ['top', '0'], ['border-bottom', '1px solid red']]) {
      expect(physicalReason(property, value), `${property}: ${value}`).toBeNull();
    }
  });

  it('reads declarations across lines and media queries, and takes a marker on the line or the line before', () => {
    const css = [
      '.a { margin-left: 1rem; }',
      '@media (max-width: 600px) {',
      '  .b { left: 0; } /* physical: over the left half */',
      '  .c {',
      '    /* physical: the picture\'s left edge */',
      '    padding-left: 2px;',
      '    right: 0;',
      '  }',
      '}',
      '.d:hover, .e::after { content: \'ab; c {\'; text-align:',
      '  right; }',
      '.f { direction: ltr; }',
      '.g { content: \' (chosen)\'; }',
      '.h::after { content: \': \'; }',
      '/* geometry */',
      '.i { direction: ltr; }',
    ].join('\n');
    expect(directionProblems(css)).toEqual([
      'line 1: margin-left (use its inline-start/end form)',
      'line 7: right: (use inset-inline-start/end)',
      'line 10: words in content: \'ab; c {\' (a catalogue message cannot reach CSS)',
      'line 10: text-align: right (use start or end)',
      'line 12: direction: ltr without a comment saying why',
      'line 13: words in content: \' (chosen)\' (a catalogue message cannot reach CSS)',
    ]);
  });
});
