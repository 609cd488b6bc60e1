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

/**
 * The note's sentence for `metal` ({ name, n, k }) with its stats (metalCurveStats): what the
 * lecture says, what the exact curves do, and the tint, each number computed here.
 */
export function metalsLectureGap(metal, stats) {
  const head = channelsAt(metal, 0);
  const grazing = channelsAt(metal, GRAZING);
  const deepest = stats.reduce((a, b) => (b.dip > a.dip ? b : a));
  const dipping = stats.filter((s) => s.dip >= NAMED_DIP).map((s) => s.channel);
  const dip = dipping.length > 0
    ? ` first dips below F0 in ${channelNames(dipping)} (by up to ${small(deepest.dip)}, ${deepest.channel}, `
      + `near ${fixed(deepest.minimum.theta, 0)}°), then`
    : '';
  const tint = spread(head) >= NEUTRAL && spread(grazing) < spread(head)
    ? `its tint fades towards white (the channels ${fixed(spread(head), 2)} apart head-on, ${fixed(spread(grazing), 2)} at ${GRAZING}°)`
    : `it is nearly neutral at every angle (its channels within ${fixed(Math.max(spread(head), spread(grazing)), 2)} of each other)`;
  const headOn = spread(head) >= NEUTRAL ? 'Head-on its F0 carries its colour' : 'Head-on it reflects every channel nearly alike';
  return `The lecture says a metal has almost no Fresnel factor. ${headOn}, `
    + `but towards grazing ${metal.name.toLowerCase()}'s R${dip} rises towards 1 in every channel: `
    + `${list(head)} at 0°, ${list(grazing)} at ${GRAZING}° (red, green, blue), and ${tint}. `
    + `Schlick's form cannot dip below F0; F82 models add that term for metals.`;
}
