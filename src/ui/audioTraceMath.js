// @ts-check
// The audio trace of an R(θ) plot, apart from sound and DOM: the pitch of a value, the cursor's
// steps, the landmarks a move passes, and the words read out. Pitch follows R over two octaves,
// 220 Hz (R = 0) to 880 Hz (R = 1), on a logarithmic scale, so that equal steps of R sound as
// equal musical intervals (a whole tone is a step of 1/12 in R).
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';
import { angle, fixed } from './format.js';

const t = messages('ui', english);

export const LOW_HZ = 220;
export const OCTAVES = 2;

/**
 * The pitch of a value in [0, 1] (clamped), or null for a value that is not a number.
 * @param {number} value
 */
export function pitchHz(value) {
  if (!Number.isFinite(value)) return null;
  return LOW_HZ * 2 ** (OCTAVES * Math.min(1, Math.max(0, value)));
}

/** Keys of the cursor: arrows 1° (with Shift 0.1°), Page Up/Down 10°, Home/End the ends. */
/** @type {Readonly<Record<string, number>>} */
const STEPS = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 10, PageDown: -10 };

/**
 * Where `key` moves a cursor at `deg` within range (degrees, on a 0.1° grid so that repeated
 * steps never drift), or null when the key is not one of the cursor's.
 * @param {number} deg
 * @param {string} key
 * @param {boolean} [fine]  Shift held: tenths of a degree
 * @param {[number, number]} [range]
 */
export function stepCursor(deg, key, fine = false, [lo, hi] = [0, 90]) {
  let next;
  if (key === 'Home') next = lo;
  else if (key === 'End') next = hi;
  else if (Object.hasOwn(STEPS, key)) next = deg + STEPS[key] * (fine && Math.abs(STEPS[key]) === 1 ? 0.1 : 1);
  else return null;
  return Math.min(hi, Math.max(lo, Math.round(next * 10) / 10));
}

/**
 * @typedef {object} Landmarks
 * @property {number | null} brewster  the Brewster angle (degrees), where Rp = 0
 * @property {number | null} critical  the critical angle (degrees); null when n_i ≤ n_t
 */

/**
 * The landmarks a move from `from` to `to` reaches or passes (each once: the one it starts on is
 * not met again as it leaves). A first placement (from === to) meets what it lands on.
 * @param {number} from
 * @param {number} to
 * @param {Landmarks} landmarks
 * @returns {('brewster' | 'critical')[]}
 */
export function cuesBetween(from, to, { brewster, critical }) {
  const lo = Math.min(from, to);
  const hi = Math.max(from, to);
  /** @param {number | null} x */
  const met = (x) => x != null && Number.isFinite(x) && (from === to ? Math.abs(x - to) < 1e-9 : x >= lo && x <= hi && x !== from);
  return /** @type {('brewster' | 'critical')[]} */ ([met(brewster) && 'brewster', met(critical) && 'critical'].filter(Boolean));
}

/**
 * Past the critical angle all light is reflected (R = 1): the total-internal-reflection range.
 * @param {number} deg
 * @param {number | null} critical
 */
export const inTir = (deg, critical) => critical != null && deg >= critical;

/**
 * The words for the cursor: θ, each curve's value there (four decimals, computed exactly by the
 * caller), and the landmark passed or the range it is in.
 * @param {number} deg
 * @param {{ label: string, value: number }[]} values
 * @param {Landmarks & { cues?: string[] }} context
 */
export function traceReadout(deg, values, { brewster, critical, cues = [] }) {
  const list = values.map((v) => t('traceValue', { curve: v.label, value: fixed(v.value, 4) })).join(', ');
  const parts = [t('traceReadout', { theta: angle(deg, 1), values: list })];
  if (cues.includes('brewster') && brewster != null) parts.push(t('tracePassedBrewster', { angle: angle(brewster) }));
  if (cues.includes('critical') && critical != null) parts.push(t('tracePassedCritical', { angle: angle(critical) }));
  else if (inTir(deg, critical)) parts.push(t('traceInTir'));
  return parts.join(' ');
}

/**
 * A sweep of a curve from `from` to `to` degrees in `seconds`: the pitch at each `step` (its
 * time from the start), whether it is in the total-internal-reflection range, and the times
 * the landmarks are passed.
 * @param {(deg: number) => number} at  the traced curve
 * @param {Landmarks} landmarks
 */
export function sweepPlan(at, { brewster, critical }, { from = 0, to = 90, seconds = 3, step = 0.5 } = {}) {
  const points = [];
  const count = Math.round((to - from) / step);
  /** @param {number} deg */
  const time = (deg) => ((deg - from) / (to - from)) * seconds;
  for (let i = 0; i <= count; i += 1) {
    const deg = from + i * step;
    points.push({ deg, t: time(deg), hz: pitchHz(at(deg)), tir: inTir(deg, critical) });
  }
  const cues = [{ kind: 'brewster', deg: brewster }, { kind: 'critical', deg: critical }]
    .flatMap(({ kind, deg }) => (deg != null && deg >= from && deg <= to ? [{ kind, deg, t: time(deg) }] : []));
  return { points, cues, seconds };
}
