// @ts-check
// The speed-accuracy panel's numbers as it shows them: display errors in 8-bit codes and timings
// as a median with its spread. Through ui/format.js, so a negative time (a method's pass less the
// baseline's, within noise) and every small error's exponent (1.2e−4) carry a real minus sign.
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';
import { fixed, precise, sci } from '../../ui/format.js';

const t = messages('speed-accuracy', english);

/** Codes to a short string: small values in scientific notation, NaN/∞ as words. */
export function formatCodes(/** @type {number} */ v) {
  if (v === Infinity || Number.isNaN(v)) return t('notFinite');
  if (v === 0) return '0';
  return v < 0.01 ? sci(v, 1) : v < 10 ? fixed(v, 2) : fixed(v, 1);
}

/** Two significant digits, as toPrecision writes them, with a real minus sign. */
const twoDigits = (/** @type {number} */ v) => precise(v, 2);

/**
 * A spread { median, min, max } of nanoseconds as "median ns [min, max]" (unit 'ms': of
 * milliseconds), '–' when there is none.
 * @param {{ median: number, min: number, max: number } | null | undefined} spread
 * @param {'ns' | 'ms'} [unit]
 */
export function formatNs(spread, unit = 'ns') {
  if (!spread || !Number.isFinite(spread.median)) return '–';
  const f = (/** @type {number} */ v) => (Math.abs(v) >= 100 ? fixed(v, 0) : Math.abs(v) >= 1 ? fixed(v, 2) : twoDigits(v));
  return t(unit === 'ms' ? 'msSpread' : 'nsSpread', { median: f(spread.median), min: f(spread.min), max: f(spread.max) });
}

/** A number with at most three decimals and no trailing zeros (an index of refraction: 1.333, 1.5). */
export const shortDecimal = (/** @type {number} */ v) => fixed(v, 3).replace(/\.?0+$/, '');
