// Where the lecture's "metal … has almost no Fresnel factor" falls short, for the metal on show:
// its reflectance head-on and at 89° per channel, the dip between, and whether its tint fades.
// Every number comes from the exact conductor Fresnel of the lab's data (src/optics/fresnel.js).
import { cosDeg } from '../../optics/angles.js';
import { fresnelConductor } from '../../optics/fresnel.js';
import { fixed, precise } from '../../ui/format.js';

export const GRAZING = 89;
export const SOURCE = 'Lazányi & Szirmay-Kalos, “Fresnel term approximations for metals”, WSCG 2005; '
  + 'Hoffman, “Generalization of Adobe’s Fresnel Model”, 2019';

/** Channels closer than this head-on are called neutral (silver, aluminium, iron in the lab's data). */
export const NEUTRAL = 0.05;

/** A dip below F0 smaller than this is not named (copper's blue: 1.2e−5); it still shows in the table. */
export const NAMED_DIP = 0.001;

const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);
const list = (rgb) => rgb.map((x) => fixed(x, 2)).join(', ');
/** Three decimals, or two significant digits where three would read 0.000. */
const small = (x) => (fixed(x, 3) === fixed(0, 3) ? precise(x, 2) : fixed(x, 3));
/** 'red', 'red and blue', 'every channel'. */
const channelNames = (names) => (names.length === 3 ? 'every channel' : names.join(' and '));

/** R per channel at θ (degrees). */
export function channelsAt(metal, theta) {
  return metal.n.map((n, ch) => fresnelConductor(cosDeg(theta), n, metal.k[ch]));
}

/** The widest spread of the channels over 0° to 89° (a 0.25° grid): { spread, theta, cool } (cool: blue above red there). */
export function widestSpread(metal) {
  let widest = { spread: -1, theta: 0, cool: false };
  for (let i = 0; i <= 4 * GRAZING; i += 1) {
    const rgb = channelsAt(metal, i / 4);
    if (spread(rgb) > widest.spread) widest = { spread: spread(rgb), theta: i / 4, cool: rgb[2] > rgb[0] };
  }
  return widest;
}

/** How far R strays from F0 in any channel between 0° and 89°: below this, the lecture's words hold. */
export const CLOSE_TO_F0 = 0.02;
const strayFromF0 = (metal, head) => Math.max(...Array.from({ length: 4 * GRAZING + 1 }, (_, i) =>
  Math.max(...channelsAt(metal, i / 4).map((r, ch) => Math.abs(r - head[ch])))));

/**
 * The note's sentence for `metal` ({ name, n, k }) with its stats (metalCurveStats): what the
 * lecture says, what the exact curves do, and the tint, each number computed here.
 */
export function metalsLectureGap(metal, stats) {
  const name = metal.name.toLowerCase();
  const head = channelsAt(metal, 0);
  const grazing = channelsAt(metal, GRAZING);
  const stray = strayFromF0(metal, head);
  const deepest = stats.reduce((a, b) => (b.dip > a.dip ? b : a));
  if (stray < CLOSE_TO_F0) {
    const three = (rgb) => rgb.map((x) => fixed(x, 3)).join(', ');
    const dips = deepest.dip >= NAMED_DIP
      ? `, dipping at most ${small(deepest.dip)} below F0 (${deepest.channel}, near ${fixed(deepest.minimum.theta, 0)}°)` : '';
    return `The lecture says a metal has almost no Fresnel factor, and for ${name} it is close: in every channel R stays within `
      + `${fixed(stray, 3)} of F0 from 0° to ${GRAZING}° (${three(head)} at 0°, ${three(grazing)} at ${GRAZING}°, red, green, blue)`
      + `${dips}, and gains its last ${small(1 - Math.min(...grazing))} towards 1 only in the final degree. `
      + 'Other metals show more of their Fresnel factor.';
  }
  const dipping = stats.filter((s) => s.dip >= NAMED_DIP).map((s) => s.channel);
  const slight = stats.filter((s) => s.dip > 0 && s.dip < NAMED_DIP).map((s) => s.channel);
  const dip = dipping.length > 0
    ? ` first dips below F0 in ${channelNames(dipping)} (by up to ${small(deepest.dip)}, ${deepest.channel}, `
      + `near ${fixed(deepest.minimum.theta, 0)}°${slight.length ? `; ${slight.join(' and ')} by under ${NAMED_DIP}` : ''}), then`
    : '';
  const widest = widestSpread(metal);
  let tint;
  if (spread(head) >= NEUTRAL && spread(grazing) < spread(head)) {
    tint = `its tint fades towards white (the channels ${fixed(spread(head), 2)} apart head-on, `
      + `${fixed(spread(grazing), 2)} at ${GRAZING}°)`;
  } else if (widest.spread < NEUTRAL) {
    tint = `it is nearly neutral at every angle (its channels within ${fixed(widest.spread, 2)} of each other)`;
  } else {
    tint = `it is nearly neutral head-on and at ${GRAZING}° (channels within ${fixed(Math.max(spread(head), spread(grazing)), 2)}), `
      + `but near ${fixed(widest.theta, 0)}° its channels are up to ${fixed(widest.spread, 2)} apart, a faint `
      + `${widest.cool ? 'cool' : 'warm'} cast`;
  }
  const headOn = spread(head) >= NEUTRAL ? 'Head-on its F0 carries its colour' : 'Head-on it reflects every channel nearly alike';
  return `The lecture says a metal has almost no Fresnel factor. ${headOn}, `
    + `but towards grazing ${name}'s R${dip} rises towards 1 in every channel: `
    + `${list(head)} at 0°, ${list(grazing)} at ${GRAZING}° (red, green, blue), and ${tint}. `
    + `Schlick's form cannot dip below F0; F82 models add that term for metals.`;
}
