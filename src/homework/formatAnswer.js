// @ts-check
// How answers and computed values are printed: the decimals a question asks for (its tolerance is
// half a unit in that place: "to 3 decimals" is ±0.0005) and one more, so a shown value is never
// rounder than the check it is held to. Shown numbers: src/ui/format.js (the page's decimal sign).
import { fixed } from '../ui/format.js';
import { number } from './questionParts.js';

/** @typedef {{ tolerance: number, unit: string | null }} Checked  a question with a value, as it is checked */

/**
 * Decimals for a value checked at this tolerance (angles: at least two).
 * @param {Checked} question
 */
export function decimalsFor(question) {
  const digits = Math.max(1, Math.ceil(-Math.log10(2 * question.tolerance) - 1e-9) + 1);
  return question.unit === 'deg' ? Math.max(2, digits) : digits;
}

/**
 * @param {Checked} question
 * @param {number} value
 */
export function formatValue(question, value) {
  const text = fixed(value, decimalsFor(question));
  return question.unit === 'deg' ? `${text}°` : text;
}

/** @param {Checked} question */
export function formatTolerance(question) {
  return question.unit === 'deg' ? `${number(question.tolerance)}°` : number(question.tolerance);
}
