// Per-channel reflectance of a metal (complex index n + ik per RGB channel) against the angle of
// incidence: exact conductor Fresnel beside Schlick's approximation with the channel's own F0,
// their largest difference, and the dip of the exact curve below F0 near grazing, which Schlick
// (rising from F0 to 1 monotonically) cannot show. Every value comes from fresnel.js.
import { conductorNormalIncidence, fresnelConductor, fresnelConductorPolarized, fresnelSchlick } from '../../optics/fresnel.js';
import { cosDeg } from '../../optics/angles.js';
import { refinedMax } from '../../optics/refinedMax.js';
import { principalAngle } from '../../optics/conductorPhase.js';

export const CHANNELS = Object.freeze(['red', 'green', 'blue']);

/**
 * The index of a dielectric (seen from air) whose R0 is f0: n = (1 + √F0)/(1 − √F0) (solve
 * R0 = ((n − 1)/(n + 1))² for n; Gulbrandsen, JCGT 3(4) 2014, n_max). fresnelSchlick on it is
 * Schlick's approximation with this F0, without a second copy of the formula. Null for F0 = 1.
 */
export function schlickIndexForF0(f0) {
  if (!(f0 >= 0 && f0 <= 1)) throw new RangeError(`F0 must be in [0, 1], got ${String(f0)}`);
  if (f0 === 1) return null;
  const r = Math.sqrt(f0);
  return (1 + r) / (1 - r);
}

/** Schlick's approximation F0 + (1 − F0)(1 − cos θ)^5 for a given F0 (1 everywhere when F0 = 1). */
export function schlickForF0(cosTheta, f0) {
  const n = schlickIndexForF0(f0);
  return n === null ? 1 : fresnelSchlick(cosTheta, 1, n);
}

/**
 * metal: { n: [r, g, b], k: [r, g, b] }. θ from 0° to 90° in `count` samples.
 * Returns { theta, f0, exact, schlick, error }, the last three as one array per channel.
 */
export function metalCurves(metal, count = 361) {
  const theta = Array.from({ length: count }, (_, i) => (90 * i) / (count - 1));
  const f0 = CHANNELS.map((_, ch) => conductorNormalIncidence(metal.n[ch], metal.k[ch]));
  const exact = CHANNELS.map(() => []);
  const schlick = CHANNELS.map(() => []);
  const error = CHANNELS.map(() => []);
  for (const t of theta) {
    const c = cosDeg(t);
    for (let ch = 0; ch < 3; ch += 1) {
      const e = fresnelConductor(c, metal.n[ch], metal.k[ch]);
      const s = schlickForF0(c, f0[ch]);
      exact[ch].push(e);
      schlick[ch].push(s);
      error[ch].push(Math.abs(e - s));
    }
  }
  return { theta, f0, exact, schlick, error };
}

/**
 * Per channel of `metal` (the one the curves are of): F0, the largest |exact − Schlick| and its
 * angle, and the lowest exact value with its angle, each refined off the grid (refinedMax.js);
 * `dip` is how far that lowest value lies below F0 (0 when the curve never drops). A conductor has
 * no Brewster angle (Rp = 0) but two stand-ins: `pseudoBrewster`, where Rp is least, and `principal`,
 * where the p–s phase difference is 90° (Born & Wolf, Principles of Optics, 7th ed., §14.2; they
 * differ by a few degrees, Azzam, JOSA A 25, 2858, 2008; conductorPhase.js).
 */
export function metalCurveStats({ theta, f0, exact, error }, metal) {
  return CHANNELS.map((name, ch) => {
    const F = (t) => fresnelConductor(cosDeg(t), metal.n[ch], metal.k[ch]);
    const worst = refinedMax(theta, error[ch], (t) => Math.abs(F(t) - schlickForF0(cosDeg(t), f0[ch])));
    const low = refinedMax(theta, exact[ch].map((v) => -v), (t) => -F(t));
    const Rp = (t) => fresnelConductorPolarized(cosDeg(t), metal.n[ch], metal.k[ch]).p;
    const leastRp = refinedMax(theta, theta.map((t) => -Rp(t)), (t) => -Rp(t));
    return {
      channel: name,
      f0: f0[ch],
      maxError: worst,
      minimum: { value: -low.value, theta: low.theta },
      dip: Math.max(0, f0[ch] - -low.value),
      pseudoBrewster: { theta: leastRp.theta, rp: -leastRp.value },
      principal: { theta: principalAngle(metal.n[ch], metal.k[ch]) },
    };
  });
}

/** The angle the lecture-gap note calls grazing (degrees): the last whole degree before 90°. */
export const GRAZING = 89;

/** R per channel at θ (degrees). */
export function channelsAt(metal, theta) {
  return metal.n.map((n, ch) => fresnelConductor(cosDeg(theta), n, metal.k[ch]));
}

const spread = (rgb) => Math.max(...rgb) - Math.min(...rgb);

/** The widest spread of the channels over 0° to 89° (a 0.25° grid): { spread, theta, cool } (cool: blue above red there). */
export function widestSpread(metal) {
  let widest = { spread: -1, theta: 0, cool: false };
  for (let i = 0; i <= 4 * GRAZING; i += 1) {
    const rgb = channelsAt(metal, i / 4);
    if (spread(rgb) > widest.spread) widest = { spread: spread(rgb), theta: i / 4, cool: rgb[2] > rgb[0] };
  }
  return widest;
}
