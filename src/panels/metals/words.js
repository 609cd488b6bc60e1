// Where the lecture's "metal … has almost no Fresnel factor" falls short, for the metal on show:
// its reflectance head-on and at 89° per channel, the dip between, and whether its tint fades.
// Every number comes from the exact conductor Fresnel of the lab's data (physics.js, src/optics/fresnel.js).
import { angle, fixed, precise } from '../../ui/format.js';
import { channelsAt, GRAZING, widestSpread } from './physics.js';
import { materialNameInText } from '../shared/materialName.js';
import english from 'virtual:messages/en/metals';
import { messages } from '../../i18n/messages.js';

const t = messages('metals', english);

/** The sources of the note, in the page's language. */
export const gapSource = () => t('gapSource');

/** Channels closer than this head-on are called neutral (silver, aluminium, iron in the lab's data). */
export const NEUTRAL = 0.05;

/** A dip below F0 smaller than this is not named (copper's blue: 1.2e−5); it still shows in the table. */
export const NAMED_DIP = 0.001;

const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);
/** Red, green and blue as the page writes three numbers. */
const list = (rgb, digits = 2) => {
  const [r, g, b] = rgb.map((x) => fixed(x, digits));
  return t('rgb', { r, g, b });
};
/** Three decimals, or two significant digits where three would read 0.000. */
const small = (x) => (fixed(x, 3) === fixed(0, 3) ? precise(x, 2) : fixed(x, 3));
/** 'red', 'red and blue', 'every channel' (the catalogue's channels, by a key such as redBlue). */
const channelNames = (names) => t('channels', {
  set: names.length === 3 ? 'all' : names.map((name, i) => (i ? name[0].toUpperCase() + name.slice(1) : name)).join(''),
});

/** How far R strays from F0 in any channel between 0° and 89°: below this, the lecture's words hold. */
export const CLOSE_TO_F0 = 0.02;
const strayFromF0 = (metal, head) => Math.max(...Array.from({ length: 4 * GRAZING + 1 }, (_, i) =>
  Math.max(...channelsAt(metal, i / 4).map((r, ch) => Math.abs(r - head[ch])))));

/**
 * The note's sentence for `metal` ({ id, n, k }) with its stats (metalCurveStats): what the
 * lecture says, what the exact curves do, and the tint, each number computed here.
 */
export function metalsLectureGap(metal, stats) {
  const name = materialNameInText(metal.id);
  const head = channelsAt(metal, 0);
  const grazing = channelsAt(metal, GRAZING);
  const stray = strayFromF0(metal, head);
  const deepest = stats.reduce((a, b) => (b.dip > a.dip ? b : a));
  const dip = {
    dips: deepest.dip >= NAMED_DIP ? 'yes' : 'no', dip: small(deepest.dip), channel: deepest.channel,
    dipAngle: angle(deepest.minimum.theta, 0),
  };
  if (stray < CLOSE_TO_F0) {
    return t('gapClose', {
      metal: name, stray: fixed(stray, 3), grazing: angle(GRAZING, 0), head: list(head, 3), graze: list(grazing, 3),
      last: small(1 - Math.min(...grazing)), ...dip,
    });
  }
  const dipping = stats.filter((s) => s.dip >= NAMED_DIP).map((s) => s.channel);
  const slight = stats.filter((s) => s.dip > 0 && s.dip < NAMED_DIP).map((s) => s.channel);
  const widest = widestSpread(metal);
  let tint = 'cast';
  if (spread(head) >= NEUTRAL && spread(grazing) < spread(head)) tint = 'fades';
  else if (widest.spread < NEUTRAL) tint = 'neutral';
  return t('gap', {
    metal: name, headOn: spread(head) >= NEUTRAL ? 'coloured' : 'neutral', head: list(head), graze: list(grazing),
    grazing: angle(GRAZING, 0), ...dip, dips: dipping.length > 0 ? 'yes' : 'no', dipping: dipping.length ? channelNames(dipping) : '',
    slightly: slight.length ? 'yes' : 'no', slight: slight.length ? channelNames(slight) : '', named: fixed(NAMED_DIP, 3),
    tint, headSpread: fixed(spread(head), 2), grazeSpread: fixed(spread(grazing), 2), widest: fixed(widest.spread, 2),
    within: fixed(Math.max(spread(head), spread(grazing)), 2), castAngle: angle(widest.theta, 0), cast: widest.cool ? 'cool' : 'warm',
  });
}
