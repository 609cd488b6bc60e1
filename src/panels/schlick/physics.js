// Exact Fresnel against Schlick's approximation on cos θi and on cos θt, sampled over θ for a
// plot, a CSV and the largest error. Pure float64 math from fresnel.js, no DOM.
import { criticalAngle, fresnelExact, fresnelSchlick, fresnelSchlickTIR } from '../../optics/fresnel.js';
import { sampleAngles, schlickErrorAt } from '../../optics/curves.js';
import { cosDeg, DEG } from '../../optics/angles.js';
import { refinedMax } from '../../optics/refinedMax.js';


/**
 * Angles in degrees: an even grid with the critical and Brewster angles (curves.js), and for
 * nI > nT also the images of an even θt grid, θi = asin((nT/nI) sin θt). Schlick on cos θt
 * is steep just below the critical angle (all of θt from 60° to 90° lies within about 7° of θi
 * for glass to air), so an even θi grid alone would miss its worst error there.
 */
export function comparisonAngles(nI, nT, count = 721) {
  const angles = sampleAngles(nI, nT, count);
  if (nI > nT) {
    for (let i = 0; i < count; i += 1) {
      const thetaT = (90 * i) / (count - 1);
      angles.push(Math.asin(Math.min(1, (nT / nI) * Math.sin(thetaT * DEG))) / DEG);
    }
  }
  return [...new Set(angles)].sort((a, b) => a - b);
}


/**
 * Curves for nI → nT: theta (degrees), exact, schlick (on cos θi, as on the slide), schlickT
 * (fresnelSchlickTIR: on cos θt when nI > nT, 1 past the critical angle; equal to schlick when
 * nI ≤ nT), their absolute errors, and the largest error of each ({ value, theta }).
 */
export function schlickComparison(nI, nT, count = 721) {
  const theta = comparisonAngles(nI, nT, count);
  const exact = [];
  const schlick = [];
  const schlickT = [];
  const error = [];
  const errorT = [];
  for (const t of theta) {
    const c = cosDeg(t);
    const e = fresnelExact(c, nI, nT);
    const s = fresnelSchlick(c, nI, nT);
    const st = fresnelSchlickTIR(c, nI, nT);
    exact.push(e);
    schlick.push(s);
    schlickT.push(st);
    error.push(Math.abs(e - s));
    errorT.push(Math.abs(e - st));
  }
  const critical = criticalAngle(nI, nT);
  return {
    theta, exact, schlick, schlickT, error, errorT,
    critical: critical === null ? null : critical / DEG,
    worst: refinedMax(theta, error, (t) => schlickErrorAt(t, nI, nT)),
    worstT: refinedMax(theta, errorT, (t) => Math.abs(fresnelExact(cosDeg(t), nI, nT) - fresnelSchlickTIR(cosDeg(t), nI, nT))),
  };
}
