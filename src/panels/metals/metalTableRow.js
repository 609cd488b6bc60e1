// The text of a metal's row per channel in the metals panel's table, apart from the DOM so that
// what the table reads is tested. Every number goes through src/ui/format.js.
import { angle, fixed, precise } from '../../ui/format.js';
import english from 'virtual:messages/en/metals';
import { messages } from '../../i18n/messages.js';

const t = messages('metals', english);

/**
 * How far below F0 a dip goes: four decimals, or two significant digits where those would read
 * 0.0000 (copper's blue dips 1.2e−5). A dip of 0 or less is none: rounding can leave a curve that
 * never drops a hair below 0, which reads 0.0000, never "−0.0000".
 * @param {number} dip
 */
export function belowF0(dip) {
  if (Number.isNaN(dip)) return t('belowF0', { value: fixed(dip, 4) });
  if (!(dip > 0)) return t('belowF0', { value: fixed(0, 4) });
  return t('belowF0', { value: fixed(dip, 4) === fixed(0, 4) ? precise(dip, 2) : fixed(dip, 4) });
}

/**
 * @typedef {{ channel: string, f0: number, maxError: { value: number, theta: number },
 *   minimum: { value: number, theta: number }, dip: number, pseudoBrewster: { theta: number, rp: number },
 *   principal: { theta: number | null } }} ChannelStats  one channel of metalCurveStats (physics.js)
 */

/**
 * The cells of channel `ch`'s row: its name, n + ik, F0, the largest |exact − Schlick|, the lowest
 * exact R (how far below F0), the pseudo-Brewster angle and the principal angle.
 * @param {{ n: number[], k: number[], rgbNm: number[] }} metal
 * @param {ChannelStats} s
 * @param {number} ch
 * @returns {string[]}
 */
export function metalTableRow(metal, s, ch) {
  const lowest = s.dip > 0
    ? t('lowest', { value: fixed(s.minimum.value, 4), angle: angle(s.minimum.theta), below: belowF0(s.dip) })
    : t('neverBelow');
  return [
    t('channelRow', { channel: s.channel, nm: String(metal.rgbNm[ch]) }),
    t('complexIndex', { n: fixed(metal.n[ch], 3), k: fixed(metal.k[ch], 3) }),
    fixed(s.f0, 4),
    t('valueAt', { value: fixed(s.maxError.value, 4), angle: angle(s.maxError.theta) }),
    lowest,
    t('pseudoBrewster', { angle: angle(s.pseudoBrewster.theta), rp: fixed(s.pseudoBrewster.rp, 3) }),
    angle(s.principal.theta),
  ];
}
