// @ts-check
// Typed parameter schemas: one source of truth per panel for its controls, its URL state and
// its messages. Pure functions; a bad value never throws, it is reported and replaced by the default
// (in the manner of PhET's query-parameter tables).
//
// Spec fields: type ('number' | 'enum' | 'color' | 'boolean' | 'text'), default, and
// for numbers min, max, step and, for an index or a count, integer: true (a whole number only);
// for enums options (an array of values); the names of a control and of its options are the
// panel's words, in the catalogue (src/panels/controlText.js);
// for texts maxLength and optionally encode/decode, a compact form for the link (decode also
// takes the plain text, which messages send; it returns null for a form it cannot read);
// optionally aliases: older keys that still read (links and decks made before a rename keep working).
// A problem's reason is a phrase in the page's language ("is not a number"), said after the key
// and the value as describeProblem writes them.
import english from 'virtual:messages/en/host';
import { messages } from '../i18n/messages.js';
import { shortNumber } from '../ui/format.js';

const t = messages('host', english);

/**
 * A value refused: the name it came under, the value as it came, why (a phrase in the page's
 * language), and for a link's value the default used instead, as the link would write it.
 * @typedef {{ key: string, raw: unknown, reason: string, fallback?: string }} Problem
 */

const HEX = /^#?([0-9a-f]{6})$/i;
// A number as a person writes one: decimal, optionally signed, with an exponent. Number() also
// takes 0x1, 0b1, 0o7 and Infinity, which no link or control writes.
const DECIMAL = /^[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?$/i;

/** @typedef {import('./panelContract.js').ParamSpec} ParamSpec */
/** @typedef {import('./panelContract.js').Schema} Schema */
/** @typedef {import('./panelContract.js').Value} Value */
/** @typedef {import('./panelContract.js').Values} Values */

/**
 * A decimal number written as text (surrounding spaces allowed), or NaN.
 * @param {string} text
 */
export function readNumber(text) {
  const trimmed = text.trim();
  return DECIMAL.test(trimmed) ? Number(trimmed) : NaN;
}

/** @param {import('./panelContract.js').EnumSpec} spec */
function enumValues(spec) {
  return Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options ?? {});
}

/**
 * Any value from outside as a short text for a notice or an error message, without running any of
 * its code: String() of an object calls its toString, which a message can set to something that
 * throws ({ toString: 'x' }), and a getter could run anything.
 * @param {unknown} raw
 */
export function rawText(raw, max = 40) {
  let text;
  if (raw === null || ['string', 'number', 'boolean', 'undefined', 'bigint'].includes(typeof raw)) text = String(raw);
  else text = t('rawKind', { kind: Array.isArray(raw) ? 'list' : typeof raw });
  return text.length > max ? `${clipText(text, max)}…` : text;
}

/**
 * At most `max` UTF-16 units of a text, without half of a character beyond the BMP at the cut (it would show as �).
 * @param {string} text
 * @param {number} max
 */
export function clipText(text, max) {
  return text.slice(0, /[\ud800-\udbff]/.test(text.charAt(max - 1)) ? max - 1 : max);
}

/**
 * Number of decimals implied by a step (0.001 → 3), used to write short, exact URLs.
 * @param {number | undefined} step
 */
export function stepDecimals(step) {
  if (!step || step >= 1) return 0;
  return Math.min(12, Math.max(0, Math.ceil(-Math.log10(step) - 1e-9)));
}

/**
 * A raw value checked: the value it stands for, or why it was refused.
 * @typedef {{ ok: true, value: Value, reason?: undefined } | { ok: false, reason: string, value?: undefined }} Parsed
 */

/**
 * Checks one raw value (a URL string, a control's value or a message field) against its spec.
 * Returns { ok: true, value } or { ok: false, reason }.
 * @param {ParamSpec} spec
 * @param {unknown} raw
 * @returns {Parsed}
 */
export function parseValue(spec, raw) {
  const { type } = spec; // as written: a schema that is not type-checked may name another type
  switch (spec.type) {
    case 'number': {
      const value = typeof raw === 'number' ? raw : typeof raw === 'string' ? readNumber(raw) : NaN;
      if (!Number.isFinite(value)) return { ok: false, reason: t('reasonNotNumber') };
      if (spec.integer && !Number.isInteger(value)) return { ok: false, reason: t('reasonNotWhole') };
      if (value < spec.min || value > spec.max) {
        return { ok: false, reason: t('reasonOutside', { min: shortNumber(spec.min), max: shortNumber(spec.max) }) };
      }
      return { ok: true, value: value + 0 }; // -0 is 0: it would print as −0 and write a link of its own
    }
    case 'enum': {
      const value = ['string', 'number', 'boolean'].includes(typeof raw) ? String(raw) : null;
      if (value === null || !enumValues(spec).includes(value)) {
        return { ok: false, reason: t('reasonNotOneOf', { values: enumValues(spec).join(', ') }) };
      }
      return { ok: true, value };
    }
    case 'color': {
      const match = typeof raw === 'string' ? HEX.exec(raw.trim()) : null;
      if (!match) return { ok: false, reason: t('reasonNotColour') };
      return { ok: true, value: `#${match[1].toLowerCase()}` };
    }
    case 'boolean': {
      if (raw === true || raw === 'true' || raw === '1') return { ok: true, value: true };
      if (raw === false || raw === 'false' || raw === '0') return { ok: true, value: false };
      return { ok: false, reason: t('reasonNotBoolean') };
    }
    case 'text': {
      if (typeof raw !== 'string') return { ok: false, reason: t('reasonNotText') };
      const text = spec.decode ? spec.decode(raw) : raw;
      if (typeof text !== 'string') return { ok: false, reason: t('reasonUnreadable') };
      if (text.length > spec.maxLength) {
        return { ok: false, reason: t('reasonTooLong', { count: spec.maxLength, max: shortNumber(spec.maxLength) }) };
      }
      return { ok: true, value: text };
    }
    default:
      return { ok: false, reason: t('reasonUnknownType', { type: rawText(type) }) };
  }
}

/**
 * Writes a value as it appears in a URL.
 * @param {ParamSpec} spec
 * @param {Value} value
 * @returns {string}
 */
export function formatValue(spec, value) {
  switch (spec.type) {
    case 'number': {
      if (typeof value !== 'number') return String(value); // not a value of this spec: written as it is
      const text = value.toFixed(stepDecimals(spec.step));
      const short = text.includes('.') ? text.replace(/\.?0+$/, '') : text;
      return short === '-0' ? '0' : short; // a tiny negative value rounds to 0, not to a link of its own
    }
    case 'color':
      return String(value).replace('#', '');
    case 'text':
      return spec.encode ? spec.encode(String(value)) : String(value);
    default:
      return String(value);
  }
}

/**
 * The schema's defaults as a fresh values object.
 * @param {Schema} schema
 * @returns {Values}
 */
export function defaults(schema) {
  return Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, spec.default]));
}

/**
 * The schema with other defaults: `start` (values already checked against it) where it has them.
 * Read and written with it, a link carries only what differs from that start, as a lecture's panel
 * that starts elsewhere than the panel's defaults needs (a key left out means the item's value).
 * @param {Schema} schema
 * @param {Readonly<Values>} start
 * @returns {Schema}
 */
export function withDefaults(schema, start) {
  /** @type {(entry: [string, ParamSpec]) => [string, ParamSpec]} */
  const startOf = ([key, spec]) => [key, Object.hasOwn(start, key)
    ? /** @type {ParamSpec} */ ({ ...spec, default: start[key] }) // start[key] was checked against this spec
    : spec];
  return Object.fromEntries(Object.entries(schema).map(startOf));
}

/**
 * The schema key a name or one of its aliases stands for, or undefined.
 * @param {Schema} schema
 * @param {string} name
 */
export function resolveKey(schema, name) {
  if (Object.hasOwn(schema, name)) return name;
  return Object.keys(schema).find((key) => schema[key].aliases?.includes(name));
}

/**
 * Reads values for a schema from URLSearchParams (or any object with get/has).
 * Keys may carry a prefix (`spheres.nT`) and may be written by an alias (`n2` for `nT`); the key
 * itself wins over an alias. Absent keys take the default silently, bad ones take the default
 * and are listed in `problems`. The values are typed from the schema (ValuesOf): each is its spec's
 * default or passed parseValue for that spec.
 * @template {Schema} S
 * @param {S} schema
 * @param {{ get(name: string): string | null, has(name: string): boolean }} search
 * @returns {{ values: import('./panelContract.js').ValuesOf<S>, problems: Problem[] }}
 */
export function readParams(schema, search, prefix = '') {
  const values = defaults(schema);
  /** @type {Problem[]} */
  const problems = [];
  for (const [key, spec] of Object.entries(schema)) {
    const name = [key, ...(spec.aliases ?? [])].map((k) => prefix + k).find((k) => search.has(k));
    if (name === undefined) continue;
    const raw = search.get(name);
    const result = parseValue(spec, raw);
    if (result.ok) {
      values[key] = result.value;
    } else {
      const fallback = spec.type !== 'text' ? formatValue(spec, spec.default)
        : spec.defaultText ? t(`defaultText.${spec.defaultText}`) : t('emptyText');
      problems.push({ key: name, raw, reason: result.reason, fallback });
    }
  }
  // Each value is of its spec's type (the default, or parsed for the spec), which is what ValuesOf says.
  return { values: /** @type {import('./panelContract.js').ValuesOf<S>} */ (values), problems };
}

/**
 * Applies a partial update (from a control, a message, the page) to values. Keys may be aliases.
 * Unknown keys and bad values are rejected and reported; the rest are applied. Returns
 * { applied, rejected, changed }: changed lists the keys whose value is now different.
 * @param {Schema} schema
 * @param {Values} values  written in place
 * @param {unknown} update  an object of names and raw values (anything else applies nothing)
 * @returns {{ applied: Values, rejected: Problem[], changed: string[] }}
 */
export function applyParams(schema, values, update) {
  /** @type {Values} */
  const applied = {};
  /** @type {Problem[]} */
  const rejected = [];
  /** @type {string[]} */
  const changed = [];
  for (const [name, raw] of Object.entries(update ?? {})) {
    const key = resolveKey(schema, name);
    if (key === undefined) {
      rejected.push({ key: name, raw, reason: t('reasonNotParameter') });
      continue;
    }
    const result = parseValue(schema[key], raw);
    if (!result.ok) {
      rejected.push({ key: name, raw, reason: result.reason });
      continue;
    }
    if (values[key] !== result.value && !changed.includes(key)) changed.push(key);
    applied[key] = values[key] = result.value;
  }
  return { applied, rejected, changed };
}

/**
 * Writes a schema's values into URLSearchParams: values that differ from their defaults are set,
 * the rest removed, so a page of many panels keeps a short link that still reproduces the view.
 * @template {URLSearchParams} S
 * @param {Schema} schema
 * @param {Readonly<Values>} values
 * @param {S} search
 * @returns {S}
 */
export function writeParams(schema, values, search, prefix = '') {
  for (const [key, spec] of Object.entries(schema)) {
    for (const alias of spec.aliases ?? []) search.delete(prefix + alias); // the link now says it by name
    const text = formatValue(spec, values[key]);
    if (text === formatValue(spec, spec.default)) search.delete(prefix + key);
    else search.set(prefix + key, text);
  }
  return search;
}

/**
 * A readable sentence for a problem, for the on-screen notice.
 * @param {Problem} problem
 */
export function describeProblem({ key, raw, reason, fallback }) {
  const words = { key: rawText(key), raw: rawText(raw), reason };
  return fallback === undefined ? t('problemIgnored', words) : t('problemUsing', { ...words, fallback });
}
