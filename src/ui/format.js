// Numbers as the panels show them: fixed decimals (a column keeps its width as a slider moves),
// a real minus sign (U+2212), which a hyphen is not, and the decimal separator of the page's
// language (es: 0,04), which Intl gives (setNumberLocale, from src/i18n/language.js). The digits are
// toFixed's, whatever the language. Numbers a program reads (CSV cells, links, code, markup) do not
// come through here: markupNumber and rounded keep the point.
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';
import { safeLocale } from './safeLocale.js';

const t = messages('ui', english);

export const MINUS = '\u2212';

let decimal = '.';

/**
 * The decimal separator of `locale` as Intl writes it ('.' where it cannot tell).
 * @param {unknown} locale
 */
export function decimalSeparator(locale) {
  try {
    return new Intl.NumberFormat(safeLocale(locale)).formatToParts(0.5).find((p) => p.type === 'decimal')?.value ?? '.';
  } catch {
    return '.';
  }
}

/**
 * Shown numbers follow `locale`'s decimal separator from now on.
 * @param {unknown} locale
 */
export function setNumberLocale(locale) {
  decimal = decimalSeparator(locale);
}

/** The separator shown numbers use now (a typed number may use it too: src/host/params.js readNumber). */
export const shownDecimal = () => decimal;

const local = (/** @type {string} */ text) => (decimal === '.' ? text : text.replace('.', decimal));

/**
 * Fixed decimals with a real minus sign; NaN (an undefined quantity) as a dash.
 * @param {number} value
 */
export function fixed(value, digits = 4) {
  if (Number.isNaN(value)) return '—';
  return local(value.toFixed(digits)).replace('-', MINUS);
}

/**
 * Scientific notation with a real minus sign, 1.234567e−8 (e+ written as e).
 * @param {number} value
 */
export function sci(value, digits = 6) {
  if (Number.isNaN(value)) return '—';
  return local(value.toExponential(digits)).replaceAll('-', MINUS).replace('e+', 'e');
}

/**
 * `digits` significant digits, as toPrecision writes them (3.14, 2.9e−7), with a real minus sign.
 * @param {number} value
 */
export function precise(value, digits = 6) {
  if (!Number.isFinite(value)) return Number.isNaN(value) ? '—' : String(value).replace('-', MINUS);
  return local(value.toPrecision(digits)).replaceAll('-', MINUS).replace('e+', 'e');
}

/**
 * An integer with its thousands apart, SI style (224850.3 → "224 850", a narrow no-break space): the
 * same in every browser language, where a comma or a point would read as a decimal to half the
 * readers (SI Brochure, 9th edition, 5.4.4).
 * @param {number} value
 */
export function grouped(value) {
  if (!Number.isFinite(value)) return Number.isNaN(value) ? '—' : String(value);
  return String(Math.round(value)).replace(/\B(?=(\d{3})+(?!\d))/g, '\u202f').replace('-', MINUS);
}

/**
 * A number as short as JavaScript writes it (a control's bound: 1, 0.0001, 1e-7), with a real minus sign.
 * @param {number} value
 */
export function shortNumber(value) {
  return local(String(value)).replaceAll('-', MINUS);
}

/**
 * An angle in degrees, 56.31°.
 * @param {number} deg
 */
export function angle(deg, digits = 2) {
  return `${fixed(deg, digits)}°`;
}

/**
 * A time taken, in seconds, as it is shown: one decimal (2.4 s), and "under 0.1 s" below a tenth
 * of a second (so a time that took something is never shown as 0.0 s).
 * @param {number} value
 */
export function seconds(value) {
  if (!Number.isFinite(value) || value < 0) return '—';
  return value < 0.1 ? t('secondsUnder', { tenth: fixed(0.1, 1) }) : t('seconds', { value: fixed(value, 1) });
}

/** A piece of a file name: lower-case letters, digits and dashes (accents dropped). */
export const fileSlug = (/** @type {unknown} */ text) => String(text).toLowerCase().normalize('NFKD')
  .replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '').slice(0, 40) || 'sheet';

/**
 * Decimals that tell ticks `incr` apart: as many as the step itself has (0.25 → 2, 2e-4 → 4).
 * uPlot's default formatter keeps three, so a range of 0 to 0.001 read 0, 0, 0, 0.001, 0.001.
 * @param {number} incr
 */
export function tickDecimals(incr) {
  if (!(incr > 0)) return 0;
  let k = 0;
  while (k < 12 && Math.abs(+incr.toFixed(k) - incr) > incr * 1e-6) k += 1;
  return k;
}

/**
 * A tick label on an axis of step `incr`: the decimals the step needs, trailing zeros dropped (0.5, 1, 1.5), real minus sign.
 * @param {number} value
 * @param {number} incr
 */
export function tickLabel(value, incr) {
  return local(String(+value.toFixed(tickDecimals(incr)))).replaceAll('-', MINUS);
}

/**
 * `value` rounded to `digits` decimals as a number (a control's step), as toFixed rounds: 0.0400 → 0.04.
 * @param {number} value
 * @param {number} digits
 */
export function rounded(value, digits) {
  return Number(value.toFixed(digits));
}

/**
 * A number that a parser reads, not a person (SVG path data and coordinates, CSS lengths,
 * aria-valuenow): fixed decimals with the ASCII hyphen-minus those grammars require.
 * @param {number} value
 * @param {number} digits
 */
export function markupNumber(value, digits) {
  return value.toFixed(digits);
}
