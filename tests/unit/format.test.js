import { describe, it, expect } from 'vitest';
import { angle, fixed, grouped, markupNumber, MINUS, precise, rounded, sci, seconds } from '../../src/ui/format.js';

describe('format: shown numbers', () => {
  it('writes a negative number with the minus sign U+2212, never a hyphen', () => {
    expect(fixed(-0.25, 3)).toBe(`${MINUS}0.250`);
    expect(angle(-12.5)).toBe(`${MINUS}12.50°`);
    expect(sci(-1.5e-8, 1)).toBe(`${MINUS}1.5e${MINUS}8`);
    expect(fixed(0.5, 2)).toBe('0.50');
  });

  it('shows an undefined quantity as a dash', () => {
    expect(fixed(NaN)).toBe('—');
  });

  it('groups the thousands of an integer with a narrow no-break space, whatever the browser language', () => {
    expect(grouped(224850.3)).toBe('224\u202f850');
    expect(grouped(299792.458)).toBe('299\u202f792');
    expect(grouped(1234567)).toBe('1\u202f234\u202f567');
    expect(grouped(999.5)).toBe('1\u202f000');
    expect(grouped(42)).toBe('42');
    expect(grouped(-12345)).toBe(`${MINUS}12\u202f345`);
    expect(grouped(NaN)).toBe('—');
  });

  it('shows a time taken in seconds, and one under a tenth of a second as "under 0.1 s", never "0.0 s"', () => {
    expect([seconds(0), seconds(0.004), seconds(0.0999), seconds(0.1), seconds(0.44), seconds(12.26)])
      .toEqual(['under 0.1 s', 'under 0.1 s', 'under 0.1 s', '0.1 s', '0.4 s', '12.3 s']);
    expect([seconds(NaN), seconds(-1)]).toEqual(['—', '—']);
  });
});

describe('format: numbers that are not shown', () => {
  it('markupNumber keeps the ASCII hyphen-minus that SVG path data and CSS lengths need', () => {
    expect(markupNumber(-3.14159, 2)).toBe('-3.14');
    expect(markupNumber(12, 1)).toBe('12.0');
  });

  it('rounded gives the number a control with that many decimals holds', () => {
    expect(rounded(0.04000000000000001, 3)).toBe(0.04);
    expect(rounded(1.000293, 6)).toBe(1.000293);
    expect(rounded(0.16955, 3)).toBe(0.17);
  });
});

describe('precise', () => {
  it('writes significant digits with a real minus sign and no e+', () => {
    expect(precise(3.14159, 3)).toBe('3.14');
    expect(precise(2.9e-7, 2)).toBe('2.9e\u22127');
    expect(precise(-0.000123456, 3)).toBe('\u22120.000123');
    expect(precise(12345678, 2)).toBe('1.2e7');
    expect(precise(NaN)).toBe('—');
    expect(precise(-Infinity)).toBe('\u2212Infinity');
  });
});
