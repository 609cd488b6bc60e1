// The two coat models of the fresnel-lighting panel in float64, twins of fresnel-lighting-mix.glsl
// (same names, same order): the lecture's k = mix(kd, ks, F) with one F at the view angle, and
// the layered coat it stands for. Pure math, no DOM; the panel's numbers and tests come from here.
import { fresnelExact } from '../../optics/fresnel.js';
import { hemisphericalReflectance } from '../../optics/diffuseFresnel.js';
import { luminance } from '../../optics/luminance.js';

/**
 * What the layered model needs of a coat of index n over air: ri, the share of diffuse light its
 * underside reflects back to the base, and re, the share of diffuse sky light it reflects above.
 */
export function coatConstants(n) {
  return { ri: hemisphericalReflectance(n, 1), re: hemisphericalReflectance(1, n) };
}

/** The lecture's coat, one channel: mix(kd, ks, F(N·V)), kd the lit diffuse colour. */
export function lectureCoat({ kd, ks, cosV, n }) {
  const F = fresnelExact(cosV, 1, n);
  return kd * (1 - F) + ks * F;
}

/**
 * A diffuse base of this albedo under a smooth clear coat of index n, one channel (Weidlich &
 * Wilkie, "Arbitrarily Layered Micro-Facet Surfaces", GRAPHITE 2007; the same closed form as
 * Mitsuba's smooth "plastic"): the coat mirrors F(N·V) of ks; the sun enters with 1 − F(N·L), the sky
 * with 1 − re; the base's light leaves with 1 − F(N·V), its radiance divided by n² as it spreads
 * into the wider cone outside, and the underside returns ri of it to the base, a geometric series
 * 1/(1 − albedo·ri). sun is N·L (0 below the horizon), sky the sky light on the base.
 */
export function layeredCoat({ albedo, sun, sky, ks, cosV, cosL, n, ri, re }) {
  const fV = fresnelExact(cosV, 1, n);
  return fV * ks + ((1 - fV) / (n * n))
    * ((albedo * ((1 - fresnelExact(cosL, 1, n)) * sun + (1 - re) * sky)) / (1 - albedo * ri));
}

/**
 * The diffuse light each model lets out, for a white sun and no sky, as a share of what the bare
 * base would reflect (albedo·N·L): the lecture's 1 − F(N·V) against the layered coat's
 * (1 − F(N·L))(1 − F(N·V))/(n²(1 − albedo·ri)).
 */
export function diffuseShares({ albedo, cosV, cosL, n, ri }) {
  const fV = fresnelExact(cosV, 1, n);
  return {
    lecture: 1 - fV,
    layered: ((1 - fresnelExact(cosL, 1, n)) * (1 - fV)) / (n * n * (1 - albedo * ri)),
  };
}

/**
 * diffuseShares for a colour kd (linear RGB), channel by channel: the layered share depends on the
 * albedo through 1/(1 − albedo·ri), so it is taken per channel and then weighed by what each
 * channel contributes to the base's luminance (Rec. 709 weights): the share of its luminance that
 * the coat lets out. Feeding kd's luminance into the formula instead would mix the channels inside
 * the nonlinear term.
 */
export function diffuseSharesRgb({ kd, cosV, cosL, n, ri }) {
  const perChannel = kd.map((albedo) => diffuseShares({ albedo, cosV, cosL, n, ri }));
  const layered = perChannel.map((s) => s.layered);
  const base = luminance(kd);
  const layeredLuminance = base > 0 ? luminance(kd.map((a, i) => a * layered[i])) / base : luminance(layered);
  return { lecture: perChannel[0].lecture, layered, layeredLuminance };
}
