// The landmarks of an R(θ) plot, drawn alike in every panel: the Brewster angle (Rp = 0), the
// critical angle with the total-internal-reflection range shaded to 90°, and a chosen θ.
// Angles in degrees, to two decimals (both landmarks are exact: atan(n_t/n_i) and asin(n_t/n_i)).
import english from 'virtual:messages/en/ui';
import { messages } from '../i18n/messages.js';
import { angle } from './format.js';

const t = messages('ui', english);

/** note: added after the angle, e.g. ' (Rp = 0)' where the plot shows Rp. */
export function brewsterMark(deg, note = '') {
  if (deg == null) return null;
  const short = t('markBrewster', { angle: angle(deg) });
  return { x: deg, color: '--c-brewster', label: `${short}${note}`, short };
}

/** null when there is no critical angle (n_i ≤ n_t). */
export function criticalMark(deg) {
  return deg == null ? null : { x: deg, color: '--c-critical', label: t('markCritical', { angle: angle(deg) }), shadeTo: 90 };
}

/** A chosen angle; the label defaults to "θ 60.00°". */
export function thetaMark(deg, label = null) {
  return deg == null ? null : { x: deg, color: '--c-marker', label: label ?? t('markTheta', { angle: angle(deg) }) };
}
