// @ts-check
// A typed answer: a number, with a decimal point or comma, and optionally its unit. Degrees may be
// written 70, 70°, 70 deg or 70 degrees; a fraction as 0.04 or as 4 %. A unit the question does
// not take is refused with a reason rather than guessed.
import { clipText } from '../host/params.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../i18n/messages.js';

const t = messages('homework', english);

/**
 * A typed answer read, or why it cannot be. (The other member's field is there, undefined, so that
 * the loose project, which cannot narrow on `ok`, reads both.)
 * @typedef {{ ok: true, value: number, reason?: undefined } | { ok: false, reason: string, value?: undefined }} ParsedAnswer
 */

const UNITS = {
  deg: ['°', 'deg', 'degree', 'degrees'],
  percent: ['%', 'percent'],
};

/**
 * unit: what the question asks for ('deg', 'fraction' or null for a plain number). Returns
 * { ok: true, value } (a fraction written in % is divided by 100) or { ok: false, reason }.
 * @param {unknown} text
 * @param {string | null} [unit]
 * @returns {ParsedAnswer}
 */
export function parseAnswer(text, unit = null) {
  // Only text is typed: an object from a stored or handed-in answer is no answer (String() of one
  // whose toString is not a function throws).
  if (typeof text !== 'string' && typeof text !== 'number') return { ok: false, reason: t('parse.noAnswer') };
  const raw = String(text).trim().toLowerCase().replace(/\s+/g, ' ');
  if (!raw) return { ok: false, reason: t('parse.noAnswer') };
  const match = /^([-+−]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:e[-+]?\d+)?)\s*([^\d\s].*)?$/.exec(raw);
  if (!match) return { ok: false, reason: t('parse.notANumber', { text: clipText(String(text), 40) }) };
  const value = Number(match[1].replace(',', '.').replace('−', '-'));
  const written = (match[2] ?? '').trim();
  if (!Number.isFinite(value)) return { ok: false, reason: t('parse.outOfRange') };
  if (!written) return { ok: true, value };
  if (unit === 'deg' && UNITS.deg.includes(written)) return { ok: true, value };
  if (unit === 'fraction' && UNITS.percent.includes(written)) return { ok: true, value: value / 100 };
  return { ok: false, reason: t('parse.notThisUnit', { unit: clipText(written, 20), wanted: unit ?? 'none' }) };
}
