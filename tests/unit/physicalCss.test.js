// Every style sheet of the lab lays out by reading direction, so that a right-to-left language is a
// catalogue and a line in languages.js, no CSS: no physical left or right unless a comment says it
// is geometry, no words in CSS, no change of direction without its reason.
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';
import { directionProblems, physicalReason } from '../../scripts/physicalCss.js';

function sheets(dir) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) return sheets(path);
    return entry.name.endsWith('.css') ? [relative('.', path).replaceAll('\\', '/')] : [];
  });
}

describe('the lab\'s style sheets', () => {
  it('use logical properties, physical ones only where marked as geometry', () => {
    const files = sheets('src');
    expect(files).toEqual(expect.arrayContaining(['src/styles.css', 'src/homework/page/homework.css', 'src/compose/compose.css',
      'src/homework/page/classView/classView.css', 'src/panels/schlick/styles.css']));
    const problems = files.flatMap((path) => directionProblems(readFileSync(path, 'utf8')).map((p) => `${path} ${p}`));
    expect(problems).toEqual([]);
  });
});

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
