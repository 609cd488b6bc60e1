// A typed answer: a number, with a decimal point or comma, and optionally its unit. Degrees may be
// written 70, 70°, 70 deg or 70 degrees; a fraction as 0.04 or as 4 %. A unit the question does
// not take is refused with a reason rather than guessed.
import { clipText } from '../host/params.js';

const UNITS = {
  deg: ['°', 'deg', 'degree', 'degrees'],
  percent: ['%', 'percent'],
};

/**
 * unit: what the question asks for ('deg', 'fraction' or null for a plain number). Returns
 * { ok: true, value } (a fraction written in % is divided by 100) or { ok: false, reason }.
 */
export function parseAnswer(text, unit = null) {
  // Only text is typed: an object from a stored or handed-in answer is no answer (String() of one
  // whose toString is not a function throws).
  if (typeof text !== 'string' && typeof text !== 'number') return { ok: false, reason: 'No answer was given.' };
  const raw = String(text).trim().toLowerCase().replace(/\s+/g, ' ');
  if (!raw) return { ok: false, reason: 'No answer was given.' };
  const match = /^([-+−]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:e[-+]?\d+)?)\s*([^\d\s].*)?$/.exec(raw);
  if (!match) return { ok: false, reason: `“${clipText(String(text), 40)}” is not a number.` };
  const value = Number(match[1].replace(',', '.').replace('−', '-'));
  const written = (match[2] ?? '').trim();
  if (!Number.isFinite(value)) return { ok: false, reason: 'That number is out of range.' };
  if (!written) return { ok: true, value };
  if (unit === 'deg' && UNITS.deg.includes(written)) return { ok: true, value };
  if (unit === 'fraction' && UNITS.percent.includes(written)) return { ok: true, value: value / 100 };
  const wanted = unit === 'deg' ? 'degrees (°)' : unit === 'fraction' ? 'a fraction (0.04) or a percentage (4 %)' : 'a plain number';
  return { ok: false, reason: `“${clipText(written, 20)}” is not a unit of this answer: it takes ${wanted}.` };
}
